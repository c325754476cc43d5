#include "render/gl_program.h"

#include <stdexcept>
#include <string>

namespace hs::render {
namespace {

// Shaders and programs report failure the same way, through their own three entry points
// (status, log, delete): one check serves both. `what` is the message up to the log.
template <class GetStatus, class GetLog, class Delete>
void throwOnFailure(GLuint object, GLenum status, GetStatus getStatus, GetLog getLog, Delete remove,
                    const std::string& what) {
  GLint ok = 0;
  getStatus(object, status, &ok);
  if (ok) return;
  char log[1024] = {};
  getLog(object, sizeof log, nullptr, log);
  remove(object);
  throw std::runtime_error(what + log);
}

GLuint compile(GLenum type, const std::vector<const char*>& sources, const char* name) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, GLsizei(sources.size()), sources.data(), nullptr);
  glCompileShader(shader);
  throwOnFailure(shader, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, glDeleteShader,
                 std::string("OpenGL shader '") + name + "' does not compile: ");
  return shader;
}

}  // namespace

GLuint linkProgram(const char* vertex, const char* fragment, const char* lighting, const char* name) {
  const GLuint program = glCreateProgram();
  std::vector<GLuint> shaders = {compile(GL_VERTEX_SHADER, {vertex}, name),
                                 compile(GL_FRAGMENT_SHADER, {fragment}, name)};
  if (lighting) shaders.push_back(compile(GL_FRAGMENT_SHADER, {"#version 330 core\n", lighting}, name));
  for (GLuint s : shaders) glAttachShader(program, s);
  glLinkProgram(program);
  for (GLuint s : shaders) glDeleteShader(s);
  throwOnFailure(program, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, glDeleteProgram,
                 std::string("OpenGL program '") + name + "' does not link: ");
  return program;
}

void setFloat(GLuint program, const char* name, float value) {
  glUniform1f(glGetUniformLocation(program, name), value);
}

void setVec3(GLuint program, const char* name, const Vec3f& v) {
  glUniform3f(glGetUniformLocation(program, name), v.x(), v.y(), v.z());
}

void setMat4(GLuint program, const char* name, const Mat4f& m) {
  glUniformMatrix4fv(glGetUniformLocation(program, name), 1, GL_FALSE, m.data());
}

void upload(GLuint buffer, const std::vector<Vec3f>& data) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(Vec3f)), data.data(), GL_STREAM_DRAW);
}

void attribute(GLuint index, GLuint buffer, GLuint divisor) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glEnableVertexAttribArray(index);
  glVertexAttribPointer(index, 3, GL_FLOAT, GL_FALSE, sizeof(Vec3f), nullptr);
  glVertexAttribDivisor(index, divisor);
}

}  // namespace hs::render
