/// @file asset_text.hpp
/// @brief Test support: the text of a file under assets/scenes/.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

namespace snow::test {

inline std::string scene_text(const std::string& name) {
    std::ifstream in(std::string(SNOW_SOURCE_DIR) + "/assets/scenes/" + name, std::ios::binary);
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}

} // namespace snow::test
