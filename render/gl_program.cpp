#include "render/gl_program.hpp"

#include <string>

#include "core/errors.hpp"

namespace gearsim::render {
namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_highlight;
uniform mat4 u_model_view;
uniform mat4 u_projection;
uniform mat3 u_normal_matrix;
out vec3 v_position;
out vec3 v_normal;
out float v_highlight;
void main() {
  vec4 p = u_model_view * vec4(a_position, 1.0);
  v_position = p.xyz;
  v_normal = u_normal_matrix * a_normal;
  v_highlight = a_highlight;
  gl_Position = u_projection * p;
}
)";

// Lights live in eye space (x right, y up, z toward the viewer): the key from the upper left
// front, the fill from the lower right. Colours arrive in linear light (the renderer squares the
// sRGB values: gamma 2) and leave through a square root — cheap on llvmpipe, close to sRGB.
constexpr const char* kFragmentShader = R"(#version 330 core
in vec3 v_position;
in vec3 v_normal;
in float v_highlight;
uniform vec3 u_colour;
uniform vec3 u_highlight_colour;
uniform int u_lit;
uniform int u_orthographic;
out vec4 frag_colour;
const vec3 kKey = normalize(vec3(-0.45, 0.6, 0.65));
const vec3 kFill = normalize(vec3(0.6, -0.35, 0.5));
void main() {
  vec3 albedo = v_highlight > 0.5 ? u_highlight_colour : u_colour;
  if (u_lit == 0) { frag_colour = vec4(sqrt(albedo), 1.0); return; }
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;  // open meshes drawn without culling
  vec3 v = u_orthographic != 0 ? vec3(0.0, 0.0, 1.0) : normalize(-v_position);
  vec3 h = normalize(kKey + v);
  float key = dot(n, kKey);
  float diffuse = 0.75 * max(key, 0.0) + 0.28 * max(dot(n, kFill), 0.0) + 0.12;
  // (n·h)^48 by repeated squaring: x^32 · x^16.
  float s = max(dot(n, h), 0.0);
  float s2 = s * s, s4 = s2 * s2, s8 = s4 * s4, s16 = s8 * s8;
  float specular = key > 0.0 ? 0.35 * s16 * s16 * s16 : 0.0;
  frag_colour = vec4(sqrt(clamp(albedo * diffuse + vec3(specular), 0.0, 1.0)), 1.0);
}
)";

GLuint compile(GLenum type, const char* source, const char* what) {
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    glDeleteShader(s);
    GEARSIM_CHECK(false, std::string(what) + " shader does not compile: " + log);
  }
  return s;
}

}  // namespace

ShadingProgram::ShadingProgram() {
  const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader, "vertex");
  const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader, "fragment");
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(program_, sizeof log, nullptr, log);
    GEARSIM_CHECK(false, std::string("shading program does not link: ") + log);
  }
  model_view = glGetUniformLocation(program_, "u_model_view");
  projection = glGetUniformLocation(program_, "u_projection");
  normal_matrix = glGetUniformLocation(program_, "u_normal_matrix");
  colour = glGetUniformLocation(program_, "u_colour");
  highlight_colour = glGetUniformLocation(program_, "u_highlight_colour");
  lit = glGetUniformLocation(program_, "u_lit");
  orthographic = glGetUniformLocation(program_, "u_orthographic");
}

ShadingProgram::~ShadingProgram() { glDeleteProgram(program_); }

}  // namespace gearsim::render
