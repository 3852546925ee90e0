// `glintlab export`: every method's shader compiles on its own (glslangValidator, spirv-val, the
// HLSL back through glslang's HLSL front end), its tables' files hold the tables, bad options are
// refused with nothing written, and a host of its own (raw GL, none of glintlab's renderer) that
// draws a sphere with the exported GLSL gets glintlab's own image of it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <glm/gtc/matrix_inverse.hpp>
#include <sstream>

#include "app/cli_fixture.hpp"
#include "core/cache_directory.hpp"
#include "export/export_command.hpp"
#include "export/texture_file.hpp"
#include "gl_fixture.hpp"
#include "scene/lights/light_kind.hpp"
#include "scene/materials/material_kind.hpp"
#include "shading/registry.hpp"
#include "tables/table_cache.hpp"

namespace fs = std::filesystem;

namespace glintlab {
namespace {

using test::Cli;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The material kind a method has code of its own for (its first), else the default.
const MaterialKind& kind_of(const MethodDescriptor& m) {
  return m.material_kinds.empty() ? default_material_kind() : find_material_kind(m.material_kinds.front());
}

// Runs a tool on `arguments`; its output in the failure message.
::testing::AssertionResult tool_accepts(const std::string& command) {
  const std::string line = command + " 2>&1";
  std::string output;
  FILE* pipe = popen(line.c_str(), "r");
  char buffer[4096];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pipe ? pclose(pipe) : -1;
  if (status == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << command << "\n" << output.substr(0, 3000);
}

class ExportEveryMethod : public Cli, public ::testing::WithParamInterface<std::string> {};

TEST_P(ExportEveryMethod, CompilesAloneAndTranslates) {
  const MethodDescriptor& m = find_method(GetParam());
  const MaterialKind& kind = kind_of(m);
  const fs::path out = scratch / "export";
  const test::CliResult r = run_glintlab("export --method " + m.id + " --material-kind " + kind.id +
                                         (kind.requires_normal_map ? " --normal-map" : "") + " --light quad -o '" +
                                         out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string stem = (out / (m.id + "." + kind.id + ".quad")).string();
  const std::string glsl = read_text(stem + ".glsl");
  EXPECT_EQ(glsl.find("#include"), std::string::npos) << "nothing left to include";
  EXPECT_EQ(glsl.find("#line"), std::string::npos);
  EXPECT_NE(glsl.find("GlintlabRadiance glintlabShade(int material"), std::string::npos);
  EXPECT_TRUE(tool_accepts("spirv-val --target-env vulkan1.1 '" + stem + ".spv'"));
  EXPECT_TRUE(tool_accepts("glslangValidator -D -V -e main -S frag -o '" + (scratch / "hlsl.spv").string() + "' '" +
                           stem + ".hlsl'"));
  EXPECT_GT(fs::file_size(stem + ".metal"), 1000u);
  // The file compiles alone (the SPIR-V beside it came from it); without its example main it is a
  // library to include in one's own shader: checked by compiling it so, with a main of our own.
  const fs::path library = scratch / "library.frag";
  std::ofstream(library) << glsl.substr(0, glsl.find('\n') + 1) << "#define GLINTLAB_NO_MAIN\n"
                         << glsl.substr(glsl.find('\n') + 1)
                         << "layout(location = 0) out vec4 c;\nvoid main() { c = vec4(glintlabShade(0, vec3(0), "
                            "vec3(0, 0, 1), vec4(1, 0, 0, 1), vec2(0), lights[0]).specular, 1); }\n";
  EXPECT_TRUE(tool_accepts("glslangValidator -V --target-env vulkan1.1 -S frag -o '" + (scratch / "lib.spv").string() +
                           "' '" + library.string() + "'"));
  // Each table file the README names is there and holds the table's values (float32 tables as they are).
  const std::string readme = read_text(out / "README.md");
  for (const Table& t : all_tables()) {
    const fs::path file = out / (t.source.id + ".table");
    if (!fs::exists(file)) continue;
    EXPECT_NE(readme.find("`" + t.source.id + ".table`"), std::string::npos) << t.source.id;
    const TextureFile f = read_texture_file(file);
    if (f.header.internal_format != GL_RGBA32F || f.header.levels != 1) continue;
    const std::vector<float> values = test::test_table_cache().load_or_generate(t.source).values;
    ASSERT_EQ(f.levels[0].size(), values.size()) << t.source.id;
    EXPECT_EQ(std::memcmp(f.levels[0].data(), values.data(), values.size() * sizeof(float)), 0) << t.source.id;
  }
}

std::vector<std::string> method_ids() {
  std::vector<std::string> ids;
  for (const MethodDescriptor& m : all_methods()) ids.push_back(m.id);
  return ids;
}

INSTANTIATE_TEST_SUITE_P(Methods, ExportEveryMethod, ::testing::ValuesIn(method_ids()),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST_F(Cli, ExportRefusesBadOptionsAndWritesNothing) {
  expect_bad_input("export --light torch", {"--light torch", "allowed: point, directional"});
  expect_bad_input("export --method nosuch", {"'nosuch'", "allowed: conventional"});
  expect_bad_input("export --method conventional,lean", {"--method conventional,lean", "one method"});
  expect_bad_input("export --method 'deliot2023{screen_space_scale=99}'", {"screen_space_scale", "0.5 .. 8"});
  expect_bad_input("export --material-kind normal-map-glints", {"normal-map-glints", "--normal-map"});
  expect_bad_input("export --driver-profile fast", {"--driver-profile fast", "allowed: hardware, software"});
}

// ---- A host of its own: raw GL, the exported file, glintlab's packed records ----

constexpr const char* kHostVertexShader = R"(#version 450 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aTangent;
layout(location = 3) in vec2 aUV;
layout(location = 0) out vec3 position;
layout(location = 1) out vec3 normal;
layout(location = 2) out vec4 tangent;
layout(location = 3) out vec2 texcoord;
uniform mat4 model, viewProj;
uniform mat3 normalMatrix;
void main() {
  vec4 world = model * vec4(aPosition, 1.0);
  position = world.xyz;
  normal = normalMatrix * aNormal;
  tangent = vec4(mat3(model) * aTangent.xyz, aTangent.w);
  texcoord = aUV;
  gl_Position = viewProj * world;
}
)";

GLuint compile(GLenum stage, const std::string& text) {
  const GLuint shader = glCreateShader(stage);
  const char* source = text.c_str();
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    ADD_FAILURE() << "the host's shader does not compile: " << log;
  }
  return shader;
}

// The table file uploaded as its header says.
GLuint upload(const TextureFile& f) {
  const TextureFileHeader& h = f.header;
  GLuint t = 0;
  glCreateTextures(h.target, 1, &t);
  const auto w = static_cast<GLsizei>(h.width), ht = static_cast<GLsizei>(h.height), d = static_cast<GLsizei>(h.depth);
  const auto levels = static_cast<GLsizei>(h.levels);
  const bool three_d = h.target == GL_TEXTURE_2D_ARRAY || h.target == GL_TEXTURE_3D;
  if (three_d) glTextureStorage3D(t, levels, h.internal_format, w, ht, d);
  else glTextureStorage2D(t, levels, h.internal_format, w, ht);
  for (GLsizei l = 0; l < levels; ++l) {
    const GLsizei lw = std::max(1, w >> l);
    const GLsizei lh = h.target == GL_TEXTURE_1D_ARRAY ? ht : std::max(1, ht >> l);
    if (three_d) glTextureSubImage3D(t, l, 0, 0, 0, lw, lh, h.target == GL_TEXTURE_2D_ARRAY ? d : std::max(1, d >> l),
                                     GL_RGBA, GL_FLOAT, f.levels[static_cast<std::size_t>(l)].data());
    else glTextureSubImage2D(t, l, 0, 0, lw, lh, GL_RGBA, GL_FLOAT, f.levels[static_cast<std::size_t>(l)].data());
  }
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(h.min_filter));
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(h.mag_filter));
  glTextureParameteri(t, GL_TEXTURE_WRAP_S, static_cast<GLint>(h.wrap_s));
  glTextureParameteri(t, GL_TEXTURE_WRAP_T, static_cast<GLint>(h.wrap_t));
  return t;
}

GLuint uniform_buffer(const void* data, std::size_t bytes) {
  GLuint b = 0;
  glCreateBuffers(1, &b);
  glNamedBufferStorage(b, static_cast<GLsizeiptr>(bytes), data, 0);
  return b;
}

// A mat3x2 as std140 stores it: three columns, each a vec2 padded to 16 bytes.
void store_std140(const glm::mat3& m, float* out) {
  for (int c = 0; c < 3; ++c) {
    out[4 * c] = m[c][0];
    out[4 * c + 1] = m[c][1];
  }
}

// The scene's one shape drawn by the host with the exported shader of `dir`; total radiance, row 0 at the top.
Image host_render(const Scene& scene, const fs::path& dir, const std::string& stem) {
  const int width = scene.film.width, height = scene.film.height;
  const GLuint program = glCreateProgram();
  const GLuint vs = compile(GL_VERTEX_SHADER, kHostVertexShader);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, read_text(dir / (stem + ".glsl")));
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  EXPECT_TRUE(linked);

  // The blocks: camera, material 0, light 0, the material's texture transforms.
  const Camera& camera = scene.camera;
  const glm::mat4 projection = camera.projection_matrix(static_cast<float>(width) / static_cast<float>(height));
  const FrameUniforms frame = frame_uniforms(camera, projection, {width, height, 1, 0}, {0, 0, 1, 0});
  std::vector<MaterialGpu> materials(kMaxMaterials);
  materials[0] = pack_material(scene.materials.at(0));
  std::vector<LightGpu> lights(kMaxLights);
  lights[0] = pack_light(scene.lights.at(0));
  const Material& m = scene.materials.at(0);
  float transforms[12 * kTextureSlots] = {};
  for (int slot = 0; slot < kTextureSlots; ++slot)
    store_std140(slot == kTextureSlotNormalMap ? glm::mat3(glm::vec3(m.normal_map_tiling, 0, 0),
                                                           glm::vec3(0, m.normal_map_tiling, 0), glm::vec3(0, 0, 1))
                                               : glm::mat3(1.0f),
                 &transforms[12 * slot]);
  const GLuint buffers[4] = {uniform_buffer(&frame, sizeof frame),
                             uniform_buffer(lights.data(), lights.size() * sizeof(LightGpu)),
                             uniform_buffer(materials.data(), materials.size() * sizeof(MaterialGpu)),
                             uniform_buffer(transforms, sizeof transforms)};
  for (GLuint b = 0; b < 4; ++b) glBindBufferBase(GL_UNIFORM_BUFFER, b, buffers[b]);
  // The tables, each at the unit its sampler is bound to in the program.
  std::vector<GLuint> textures;
  for (const Table& t : all_tables()) {
    const fs::path file = dir / (t.source.id + ".table");
    if (!fs::exists(file)) continue;
    const GLint location = glGetUniformLocation(program, t.sampler.c_str());
    if (location < 0) continue;  // declared, not read by this GL's compiled program
    GLint unit = -1;
    glGetUniformiv(program, location, &unit);
    textures.push_back(upload(read_texture_file(file)));
    glBindTextureUnit(static_cast<GLuint>(unit), textures.back());
  }

  // The shape's mesh, interleaved as the vertex shader reads it.
  const Shape& shape = scene.shapes.at(0);
  const Mesh& mesh = *shape.mesh;
  std::vector<float> vertices;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = mesh.positions[i], n = mesh.normals[i];
    const glm::vec4 t = mesh.tangents.empty() ? glm::vec4(1, 0, 0, 1) : mesh.tangents[i];
    const glm::vec2 uv = mesh.uvs.empty() ? glm::vec2(0) : mesh.uvs[i];
    vertices.insert(vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y, t.z, t.w, uv.x, uv.y});
  }
  GLuint vbo = 0, ibo = 0, vao = 0;
  glCreateBuffers(1, &vbo);
  glNamedBufferStorage(vbo, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)), vertices.data(), 0);
  glCreateBuffers(1, &ibo);
  glNamedBufferStorage(ibo, static_cast<GLsizeiptr>(mesh.indices.size() * 4), mesh.indices.data(), 0);
  glCreateVertexArrays(1, &vao);
  glVertexArrayVertexBuffer(vao, 0, vbo, 0, 12 * sizeof(float));
  glVertexArrayElementBuffer(vao, ibo);
  const GLint sizes[4] = {3, 3, 4, 2};
  GLuint offset = 0;
  for (GLuint a = 0; a < 4; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offset * sizeof(float));
    glVertexArrayAttribBinding(vao, a, 0);
    offset += static_cast<GLuint>(sizes[a]);
  }

  // An RGBA32F target with depth, cleared to black; the mesh drawn once.
  GLuint colour[2] = {}, depth = 0, fbo = 0;
  glCreateTextures(GL_TEXTURE_2D, 2, colour);
  for (GLuint c : colour) glTextureStorage2D(c, 1, GL_RGBA32F, width, height);
  glCreateRenderbuffers(1, &depth);
  glNamedRenderbufferStorage(depth, GL_DEPTH_COMPONENT32F, width, height);
  glCreateFramebuffers(1, &fbo);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, colour[0], 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, colour[1], 0);
  glNamedFramebufferRenderbuffer(fbo, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  const GLenum draw_buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(fbo, 2, draw_buffers);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, width, height);
  const float black[4] = {0, 0, 0, 0};
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(fbo, GL_COLOR, 0, black);
  glClearNamedFramebufferfv(fbo, GL_COLOR, 1, black);
  glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &far_depth);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glUseProgram(program);
  const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(shape.transform));
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "model"), 1, GL_FALSE, &shape.transform[0][0]);
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "viewProj"), 1, GL_FALSE, &frame.view_proj[0][0]);
  glProgramUniformMatrix3fv(program, glGetUniformLocation(program, "normalMatrix"), 1, GL_FALSE, &normal_matrix[0][0]);
  glBindVertexArray(vao);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.indices.size()), GL_UNSIGNED_INT, nullptr);
  Image image(width, height);
  std::vector<float> texels(static_cast<std::size_t>(width) * height * 4);
  glGetTextureImage(colour[0], 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* p = &texels[(static_cast<std::size_t>(height - 1 - y) * width + x) * 4];
      image.at(x, y) = {p[0], p[1], p[2]};
    }
  check_gl("the export test's host");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fbo);
  glDeleteTextures(2, colour);
  glDeleteRenderbuffers(1, &depth);
  glDeleteVertexArrays(1, &vao);
  glDeleteBuffers(1, &vbo);
  glDeleteBuffers(1, &ibo);
  glDeleteBuffers(4, buffers);
  glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
  glDeleteShader(vs);
  glDeleteShader(fs);
  glDeleteProgram(program);
  return image;
}

struct HostCase {
  const char* method;
  test::TestScene scene;
};

class ExportedShaderHost : public ::testing::TestWithParam<int> {
 protected:
  test::ScratchDirectory scratch;
};

HostCase host_case(int i) {
  test::TestScene sphere;
  sphere.film(48, 36).camera({0.3, 0.4, 3.2}, {0, 0, 0}, 40).point_light({1.5, 2.0, 2.5}, 20);
  switch (i) {
    case 0:  // the baseline: a smooth lobe
      return {"conventional", sphere.material("m", {{"alpha", 0.2}, {"f0", 0.8}}).sphere("m")};
    case 1:  // the pixel's corners (attributesAtOffset on the entry point's inputs)
      return {"podee", sphere.material("m", {{"alpha", 0.02}, {"f0", 0.8}}).sphere("m")};
    default:  // glints: random numbers per uv cell and footprint
      return {"deliot2023", sphere
                                .material("m", {{"type", "binomial-glints"},
                                                {"alpha", 0.3},
                                                {"log_density", 12},
                                                {"microfacet_roughness", 0.02},
                                                {"f0", 0.9}})
                                .sphere("m")};
  }
}

TEST_P(ExportedShaderHost, DrawsTheSphereAsGlintlabDoes) {
  HostCase c = host_case(GetParam());
  test::SceneFixture glintlab_scene(c.scene);
  const Image ours = glintlab_scene.method(c.method).total;
  const Scene& scene = glintlab_scene.scene;
  const MaterialKind& kind = *scene.materials.at(0).kind;
  ExportOptions o;
  o.method = c.method;
  o.material_kind = kind.id;
  o.light = "point";
  o.driver_profile = choose_driver_profile(test::context()) == DriverProfile::Software ? "software" : "hardware";
  o.out = (scratch / "export").string();
  run_export(o);
  test::context().make_current();  // the export made a context of its own for its tables
  const Image host = host_render(scene, o.out, std::string(c.method) + "." + kind.id + ".point");
  double largest = 0, lit = 0;
  for (std::size_t p = 0; p < ours.pixel_count(); ++p) {
    const glm::vec3 d = glm::abs(host.pixels()[p] - ours.pixels()[p]);
    largest = std::max(largest, static_cast<double>(std::max(d.x, std::max(d.y, d.z))));
    lit += ours.pixels()[p].x > 0.0f ? 1 : 0;
  }
  EXPECT_GT(lit, ours.pixel_count() / 4.0) << "the sphere covers the film";
  EXPECT_LE(largest, 1e-5) << c.method;
}

INSTANTIATE_TEST_SUITE_P(Methods, ExportedShaderHost, ::testing::Values(0, 1, 2),
                         [](const auto& info) { return std::string(host_case(info.param).method); });

}  // namespace
}  // namespace glintlab
