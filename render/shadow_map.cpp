#include "render/shadow_map.hpp"

#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/camera.hpp"
#include "render/gl.hpp"

namespace umbra {

glm::dmat4 cube_face_view_projection(const glm::dvec3& light, int face, double near) {
  // GL's cube map conventions (the OpenGL 3.3 specification, table 3.19).
  static const glm::dvec3 forward[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  static const glm::dvec3 up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  return infinite_perspective(90.0, 1.0, near) * glm::lookAt(light, light + forward[face], up[face]);
}

ShadowMap::ShadowMap(int size) : size_(size) {
  glGenTextures(1, &cube_);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube_);
  for (int face = 0; face < 6; ++face)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_R32F, size, size, 0, GL_RED, GL_FLOAT, nullptr);
  // Nearest texel: filtering distances across a silhouette would invent surfaces.
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  for (const GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTexParameteri(GL_TEXTURE_CUBE_MAP, wrap, GL_CLAMP_TO_EDGE);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X, cube_, 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("the shadow map's framebuffer is incomplete (status " + std::to_string(status) + ")");
}

ShadowMap::~ShadowMap() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteRenderbuffers(1, &depth_);
  glDeleteTextures(1, &cube_);
}

void ShadowMap::begin_face(int face) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(face), cube_, 0);
  glViewport(0, 0, size_, size_);
  glClearColor(3.0e38f, 0.0f, 0.0f, 0.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void ShadowMap::end() const { glBindFramebuffer(GL_FRAMEBUFFER, 0); }

void ShadowMap::bind(int unit) const {
  glActiveTexture(GL_TEXTURE0 + GLenum(unit));
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube_);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace umbra
