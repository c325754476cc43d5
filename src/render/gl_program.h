#pragma once
// Small OpenGL helpers of the scene renderer: shader programs built from GLSL sources, uniforms
// set by name, and vertex attributes fed from arrays of Vec3f. Need a current OpenGL 3.3 core
// context (GlContext).
#include <epoxy/gl.h>

#include <vector>

#include "render/camera.h"

namespace hs::render {

// A program from a vertex and a fragment shader; `lighting`, when given, is a second fragment
// shader object that supplies functions the fragment shader declares (shaders::kLighting).
// Throws std::runtime_error with the driver's log when a shader does not compile or the
// program does not link; `name` says which.
GLuint linkProgram(const char* vertex, const char* fragment, const char* lighting, const char* name);

void setFloat(GLuint program, const char* name, float value);
void setVec3(GLuint program, const char* name, const Vec3f& v);
void setMat4(GLuint program, const char* name, const Mat4f& m);

// Copies `data` into `buffer` for this frame's draw calls.
void upload(GLuint buffer, const std::vector<Vec3f>& data);
// Feeds attribute `index` with the Vec3f of `buffer`: one per vertex (divisor 0) or one per
// instance (divisor 1).
void attribute(GLuint index, GLuint buffer, GLuint divisor = 0);

}  // namespace hs::render
