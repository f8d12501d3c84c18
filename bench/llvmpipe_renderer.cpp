// EGL surfaceless + OpenGL 3.3 core baseline; see llvmpipe_renderer.h.
#include "llvmpipe_renderer.h"

#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

namespace vlit::bench {

struct LlvmpipeRenderer::State {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  GLuint framebuffer = 0, color = 0, depth = 0, program = 0, vao = 0, buffers[3] = {0, 0, 0};
  GLint matrix_location = -1;
  GLsizei index_count = 0;
  int width = 0, height = 0;
};

namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 color;
uniform mat4 clip_from_world;
out vec3 vertex_color;
void main() {
  gl_Position = clip_from_world * vec4(position, 1.0);
  vertex_color = color;
})";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec3 vertex_color;
out vec4 frag_color;
void main() { frag_color = vec4(vertex_color, 1.0); })";

GLuint compile(GLenum type, const char* source, std::string* error) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    *error = std::string("shader compilation failed: ") + log;
    return 0;
  }
  return shader;
}

}  // namespace

std::unique_ptr<LlvmpipeRenderer> LlvmpipeRenderer::create(int width, int height, std::string* error) {
  auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_platform_display) {
    *error = "EGL has no eglGetPlatformDisplayEXT";
    return nullptr;
  }
  std::unique_ptr<LlvmpipeRenderer> r(new LlvmpipeRenderer);
  r->state_ = std::make_unique<State>();
  State& s = *r->state_;
  s.width = width;
  s.height = height;
  s.display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (s.display == EGL_NO_DISPLAY || !eglInitialize(s.display, &major, &minor)) {
    *error = "cannot initialise an EGL surfaceless display (is libgl1-mesa-dri installed?)";
    return nullptr;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    *error = "EGL cannot bind the OpenGL API";
    return nullptr;
  }
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint config_count = 0;
  const bool have_config = eglChooseConfig(s.display, config_attributes, &config, 1, &config_count) && config_count > 0;
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  s.context = eglCreateContext(s.display, have_config ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, context_attributes);
  if (s.context == EGL_NO_CONTEXT || !eglMakeCurrent(s.display, EGL_NO_SURFACE, EGL_NO_SURFACE, s.context)) {
    *error = "cannot create an OpenGL 3.3 core context without a surface";
    return nullptr;
  }

  glGenRenderbuffers(1, &s.color);
  glBindRenderbuffer(GL_RENDERBUFFER, s.color);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glGenRenderbuffers(1, &s.depth);
  glBindRenderbuffer(GL_RENDERBUFFER, s.depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glGenFramebuffers(1, &s.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, s.framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, s.color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, s.depth);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    *error = "offscreen framebuffer incomplete";
    return nullptr;
  }
  const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader, error);
  const GLuint fs = vs ? compile(GL_FRAGMENT_SHADER, kFragmentShader, error) : 0;
  if (!fs) return nullptr;
  s.program = glCreateProgram();
  glAttachShader(s.program, vs);
  glAttachShader(s.program, fs);
  glLinkProgram(s.program);
  GLint linked = 0;
  glGetProgramiv(s.program, GL_LINK_STATUS, &linked);
  if (!linked) {
    *error = "shader program does not link";
    return nullptr;
  }
  s.matrix_location = glGetUniformLocation(s.program, "clip_from_world");
  glGenVertexArrays(1, &s.vao);
  glGenBuffers(3, s.buffers);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DITHER);
  return r;
}

LlvmpipeRenderer::~LlvmpipeRenderer() {
  if (!state_ || state_->display == EGL_NO_DISPLAY) return;
  eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (state_->context != EGL_NO_CONTEXT) eglDestroyContext(state_->display, state_->context);
  eglTerminate(state_->display);
}

std::string LlvmpipeRenderer::renderer() const {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return name ? name : "?";
}

void LlvmpipeRenderer::upload(const std::vector<float>& positions, const std::vector<float>& colors,
                              const std::vector<uint32_t>& indices) {
  State& s = *state_;
  glBindVertexArray(s.vao);
  glBindBuffer(GL_ARRAY_BUFFER, s.buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(positions.size() * sizeof(float)), positions.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, s.buffers[1]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(colors.size() * sizeof(float)), colors.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s.buffers[2]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(uint32_t)), indices.data(), GL_STATIC_DRAW);
  s.index_count = GLsizei(indices.size());
}

void LlvmpipeRenderer::draw(const std::array<float, 16>& clip_from_world_column_major, const std::array<float, 3>& background) {
  State& s = *state_;
  glBindFramebuffer(GL_FRAMEBUFFER, s.framebuffer);
  glClearColor(background[0], background[1], background[2], 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(s.program);
  glUniformMatrix4fv(s.matrix_location, 1, GL_FALSE, clip_from_world_column_major.data());
  glBindVertexArray(s.vao);
  glDrawElements(GL_TRIANGLES, s.index_count, GL_UNSIGNED_INT, nullptr);
  glFinish();
}

std::vector<uint8_t> LlvmpipeRenderer::read_rgb8() const {
  const State& s = *state_;
  std::vector<uint8_t> rgba(size_t(s.width) * s.height * 4), rgb(size_t(s.width) * s.height * 3);
  glBindFramebuffer(GL_FRAMEBUFFER, s.framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, s.width, s.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  for (int y = 0; y < s.height; ++y)  // OpenGL's rows start at the bottom
    for (int x = 0; x < s.width; ++x)
      for (int k = 0; k < 3; ++k)
        rgb[(size_t(y) * s.width + x) * 3 + k] = rgba[(size_t(s.height - 1 - y) * s.width + x) * 4 + k];
  return rgb;
}

}  // namespace vlit::bench
