// snow_bench: Google Benchmark's main plus --smoke, which CI uses to run each
// benchmark once at its smallest size (numbers from a smoke run mean nothing).
#include "bench_scene.hpp"

#include <cstring>
#include <string>
#include <vector>

namespace snow::bench {
namespace {
bool smoke_flag = false;
}
bool smoke() { return smoke_flag; }
} // namespace snow::bench

int main(int argc, char** argv) {
    std::vector<char*> args;
    std::string min_time = "--benchmark_min_time=0";
    std::string filter = "--benchmark_filter=/(10000|64|0)(/|$)";
    for (int i = 0; i < argc; ++i) {
        if (std::strcmp(argv[i], "--smoke") == 0) {
            snow::bench::smoke_flag = true;
            args.push_back(min_time.data());
            args.push_back(filter.data());
        } else {
            args.push_back(argv[i]);
        }
    }
    int n = static_cast<int>(args.size());
    benchmark::Initialize(&n, args.data());
    if (benchmark::ReportUnrecognizedArguments(n, args.data())) {
        return 2;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
