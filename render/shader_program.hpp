#pragma once
// A linked GLSL program with uniform setters. Compile and link errors throw
// std::runtime_error with the driver's log.

#include <string>
#include <unordered_map>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace umbra {

class ShaderProgram {
 public:
  ShaderProgram(const std::string& name, const std::string& vertex_source, const std::string& fragment_source);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const;
  void set(const char* uniform, int value);
  void set(const char* uniform, float value);
  void set(const char* uniform, const glm::ivec2& value);
  void set(const char* uniform, const glm::vec3& value);
  void set(const char* uniform, const glm::vec4& value);
  void set(const char* uniform, const glm::mat3& value);
  void set(const char* uniform, const glm::mat4& value);

 private:
  int location(const char* uniform);
  unsigned id_ = 0;
  std::string name_;
  std::unordered_map<std::string, int> locations_;
};

}  // namespace umbra
