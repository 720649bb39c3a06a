#pragma once
// 3MF's units of length, as its XML names them, in the order of lib3mf's
// eModelUnit (MODELUNIT_MICROMETER = 0 ... MODELUNIT_METER = 5): the 3MF
// reader names a file's unit by it, and the writer gives it back.

#include <array>
#include <string_view>

namespace umbra {

inline constexpr std::array<std::string_view, 6> kThreeMfUnits = {"micron", "millimeter", "centimeter", "inch", "foot", "meter"};

}  // namespace umbra
