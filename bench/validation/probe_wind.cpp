// The wind field's ground against the flow round a surface-mounted cube
// [MT93] (reattachment about 1.6 h behind it) and against a closed
// building's still air: one steady-wind run over a ground surface that lies
// above the bounds floor (tests/scenes/ground_wind.hpp).
#include "bench/validation/validation.hpp"

#include "tests/scenes/ground_wind.hpp"

namespace snow::validation {

std::vector<Row> ground_wind(const Plan& plan) {
    const GroundCubeWake w =
        plan.quick ? ground_cube_wake(CubeShape::box, 4.0, 2.0) : ground_cube_wake(CubeShape::box);
    const std::string scene =
        "2 m cube on a ground 0.5 m above the bounds floor, steady 2 m/s, field cells "
        "0.25 × 0.5 × 0.25 m, mean over 8 s after 20 s";
    return {
        {"wind inside a closed building / free wind", "still air inside its walls",
         scene + ", footprint 0.1 and 0.25 m above the ground", w.inside_over_free, "", 0.0, 0.05},
        {"reattachment length / h behind a surface-mounted cube", "1.6 h [MT93]",
         scene + ", centreline 0.25 m above the ground", w.reattachment_over_h, "h", 1.2, 2.0},
    };
}

} // namespace snow::validation
