/// @file fft.hpp
/// @brief A radix-2 complex FFT of our own, in 1-D and composed into 3-D, for
/// the far-field snow volume [LZ]. Debian's kissfft failed on the 3-D
/// real plan and FFTW's GPL does not fit (docs/toolchain.md "FFT"). CPU only, no GL.
#pragma once

#include <complex>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace snow {

using Complex = std::complex<double>;

/// forward: X_k = Σ x_n e^(−2πi·kn/N); inverse: e^(+2πi·kn/N) and a factor 1/N,
/// so inverse(forward(x)) returns x.
enum class FftDirection : std::uint8_t { forward, inverse };

/// True for 1, 2, 4, 8, ...
[[nodiscard]] constexpr bool is_power_of_two(std::size_t n) {
    return n != 0 && (n & (n - 1)) == 0;
}

/// Twiddle factors and the bit-reversal permutation of one power-of-two length.
class FftPlan {
  public:
    /// Throws std::invalid_argument naming `n` unless it is a power of two.
    explicit FftPlan(std::size_t n);
    /// Transform length.
    [[nodiscard]] std::size_t size() const { return n_; }
    /// Transforms `data` (exactly size() elements) in place; throws
    /// std::invalid_argument on a size mismatch.
    void transform(std::span<Complex> data, FftDirection direction) const;

  private:
    std::size_t n_;
    std::vector<Complex> twiddle_;       // e^(−2πi·k/n), k < n/2, each from cos/sin directly
    std::vector<std::uint32_t> reverse_; // bit-reversed index of each position
};

/// Transforms a volume stored x fastest (index x + nx·(y + ny·z)) along all
/// three axes. Each size must be a power of two and volume.size() == nx·ny·nz;
/// throws std::invalid_argument otherwise.
void fft_3d(std::span<Complex> volume, std::size_t nx, std::size_t ny, std::size_t nz,
            FftDirection direction);

} // namespace snow
