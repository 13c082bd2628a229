#include "systems/geometry/geometry.hpp"

namespace snow {

void check_box(Invalid& e, std::string_view prefix, const Aabb& box) {
    check_fields(e, prefix, aabb_fields, box);
    static constexpr std::string_view lo[] = {"min.x", "min.y", "min.z"};
    static constexpr std::string_view hi[] = {"max.x", "max.y", "max.z"};
    for (int a = 0; a < 3; ++a) {
        check::ordered(e, prefix, lo[a], box.min[a], hi[a], box.max[a]);
    }
}

Invalid validate(const Aabb& box) {
    Invalid e;
    check_box(e, "box", box);
    return e;
}

Invalid validate_porosity(float porosity) {
    Invalid e;
    check_field(e, "box", "porosity", from_below(0.0, 1.0), porosity);
    return e;
}

} // namespace snow
