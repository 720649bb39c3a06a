#pragma once
// What the 3MF reader and writer share of lib3mf's C API: an object's
// release, its last error, the transform's layout and the units' names.

#include <array>
#include <string>
#include <string_view>

#include <glm/mat4x4.hpp>

#include <Model/COM/NMR_DLLInterfaces.h>

namespace umbra::lib3mf {

// Releases a lib3mf object when it leaves scope.
struct Held {
  NMR::PLib3MFBase* object = nullptr;
  Held() = default;
  Held(const Held&) = delete;
  Held& operator=(const Held&) = delete;
  ~Held() {
    if (object) NMR::lib3mf_release(object);
  }
};

// What lib3mf last said went wrong with `source`; "" when it says nothing.
inline std::string last_error(NMR::PLib3MFBase* source) {
  DWORD code = 0;
  LPCSTR message = nullptr;
  if (source) NMR::lib3mf_getlasterror(source, &code, &message);
  return message ? message : "";
}

// A 3MF transform acts on row vectors (p' = p M, M 4x3); lib3mf stores it as
// fields[row][column] of the 3x4 matrix that acts on column vectors.
inline glm::dmat4 to_glm(const NMR::MODELTRANSFORM& t) {
  glm::dmat4 m(1.0);
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column) m[column][row] = t.m_fFields[row][column];
  return m;
}
inline NMR::MODELTRANSFORM to_3mf(const glm::dmat4& m) {
  NMR::MODELTRANSFORM t;
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column) t.m_fFields[row][column] = float(m[column][row]);
  return t;
}

// 3MF's units of length, as its XML names them, in the order of lib3mf's
// eModelUnit (MODELUNIT_MICROMETER = 0 ... MODELUNIT_METER = 5).
inline constexpr std::array<std::string_view, 6> kUnits = {"micron", "millimeter", "centimeter", "inch", "foot", "meter"};

}  // namespace umbra::lib3mf
