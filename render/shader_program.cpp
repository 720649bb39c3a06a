#include "render/shader_program.hpp"

#include <stdexcept>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "render/gl.hpp"

namespace umbra {
namespace {

// The info log of a shader (glGetShaderiv, glGetShaderInfoLog) or a program
// (glGetProgramiv, glGetProgramInfoLog).
template <typename GetIv, typename GetLog>
std::string info_log(GLuint object, GetIv get_iv, GetLog get_log) {
  GLint length = 0;
  get_iv(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(size_t(length) + 1);
  get_log(object, length, nullptr, log.data());
  return log.data();
}

GLuint compile(GLenum stage, const std::string& source, const std::string& name) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(shader, glGetShaderiv, glGetShaderInfoLog);
    glDeleteShader(shader);
    throw std::runtime_error("shader " + name + (stage == GL_VERTEX_SHADER ? " (vertex)" : " (fragment)") +
                             " does not compile: " + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& name, const std::string& vertex_source,
                             const std::string& fragment_source)
    : name_(name) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex_source, name);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragment_source, name);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(id_, glGetProgramiv, glGetProgramInfoLog);
    glDeleteProgram(id_);
    throw std::runtime_error("shader " + name + " does not link: " + log);
  }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(id_); }

void ShaderProgram::use() const { glUseProgram(id_); }

int ShaderProgram::location(const char* uniform) {
  const auto found = locations_.find(uniform);
  if (found != locations_.end()) return found->second;
  const int at = glGetUniformLocation(id_, uniform);
  locations_.emplace(uniform, at);  // -1 (unused by this program) is ignored by glUniform*
  return at;
}

void ShaderProgram::set(const char* uniform, int value) { glUniform1i(location(uniform), value); }
void ShaderProgram::set(const char* uniform, float value) { glUniform1f(location(uniform), value); }
void ShaderProgram::set(const char* uniform, const glm::ivec2& value) {
  glUniform2iv(location(uniform), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* uniform, const glm::vec3& value) {
  glUniform3fv(location(uniform), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* uniform, const glm::vec4& value) {
  glUniform4fv(location(uniform), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* uniform, const glm::mat3& value) {
  glUniformMatrix3fv(location(uniform), 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::set(const char* uniform, const glm::mat4& value) {
  glUniformMatrix4fv(location(uniform), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace umbra
