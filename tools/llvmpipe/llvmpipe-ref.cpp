// llvmpipe-ref: renders one frame of a zrender scene with OpenGL on Mesa's llvmpipe (OSMesa, no
// window), with GLSL shaders that compute zrender's shading modes, and times it, so that
// zrender's frame time can be set beside a production software rasterizer's (compare.py).
//
//   llvmpipe-ref MODEL.obj CAMERAS.json --mode flat|normal|phong|texture [--texture PNG]
//                [--width W --height H] [--repeat N] [-o out.png]
//
// CAMERAS.json is zrender's camera manifest (zrender SCENE --cameras FILE --cameras-only): its
// first view's view and projection matrices, with an identity model matrix (the reference
// scenes'). Threads: llvmpipe's LP_NUM_THREADS. Prints one JSON line on stdout.

#define GL_GLEXT_PROTOTYPES 1  // libOSMesa exports the GL 4.5 entry points itself
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <json/json.h>
#include <tiny_obj_loader.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

enum class Mode { Flat, Normal, Phong, Texture };
const char* const kModeNames[] = {"flat", "normal", "phong", "texture"};

struct Options {
  std::string model, cameras, texture, output;
  Mode mode = Mode::Phong;
  int width = 0, height = 0;  // 0: the manifest's "w" and "h"
  int repeat = 10;
};

struct Camera {
  std::array<float, 16> view{}, projection{};  // column-major, as glUniformMatrix4fv takes them
  int width = 0, height = 0;
};

// One corner as the vertex shader reads it.
struct Vertex {
  float position[3];
  float normal[3];    // model space: the corner's normal, or the face's (per-face modes)
  float uv[2];        // OBJ texture coordinates, v = 0 at the bottom of the image
  float centroid[3];  // the face's (flat mode's light direction is taken from it)
};

struct Geometry {
  std::vector<Vertex> vertices;
  std::vector<GLuint> indices;         // triangles
  bool perFace = false;                // one color per face (flat; normal without vn)
  float base[3] = {0.8f, 0.8f, 0.8f};  // diffuse color: zrender's default, or the material's
  std::string texture;                 // the material's map_Kd, when --texture is not given
};

[[noreturn]] void fail(const std::string& message) {
  throw std::runtime_error(message);
}

Options parseOptions(int argc, char** argv) {
  Options o;
  std::vector<std::string> positional;
  bool modeGiven = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) fail(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--mode") {
      const std::string name = value();
      const auto found = std::find(std::begin(kModeNames), std::end(kModeNames), name);
      if (found == std::end(kModeNames)) fail("unknown --mode " + name);
      o.mode = Mode(found - std::begin(kModeNames));
      modeGiven = true;
    } else if (arg == "--texture") {
      o.texture = value();
    } else if (arg == "--width" || arg == "--height" || arg == "--repeat") {
      const int n = std::stoi(value());
      (arg == "--width" ? o.width : arg == "--height" ? o.height : o.repeat) = std::max(1, n);
    } else if (arg == "-o") {
      o.output = value();
    } else if (arg.empty() || arg[0] == '-') {
      fail("unknown option " + arg);
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.size() != 2 || !modeGiven)
    fail(
        "usage: llvmpipe-ref MODEL.obj CAMERAS.json --mode flat|normal|phong|texture "
        "[--texture PNG] [--width W --height H] [--repeat N] [-o out.png]");
  o.model = positional[0];
  o.cameras = positional[1];
  return o;
}

Camera readCamera(const std::string& path) {
  std::ifstream in(path);
  Json::Value root;
  std::string errors;
  if (!in || !Json::parseFromStream(Json::CharReaderBuilder(), in, &root, &errors))
    fail(path + ": cannot read the camera manifest " + errors);
  const Json::Value& frame = root["frames"][0]["zrender"];
  // The manifest's matrices are rows of 4 (row-major); GL wants columns.
  const auto columnMajor = [&](const char* key) {
    std::array<float, 16> m{};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) {
        const Json::Value& v = frame[key][r][c];
        if (!v.isNumeric()) fail(path + ": frames[0].zrender." + key + " is not a 4x4 matrix");
        m[size_t(c * 4 + r)] = float(v.asDouble());
      }
    return m;
  };
  return {columnMajor("view_matrix"), columnMajor("projection_matrix"), root["w"].asInt(),
          root["h"].asInt()};
}

using Vec3d = std::array<double, 3>;

// v / |v|, or `otherwise` for a zero vector (zrender: a degenerate face's normal is 0, a zero
// smooth normal +Z).
Vec3d normalized(const Vec3d& v, const Vec3d& otherwise) {
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(length > 0.0)) return otherwise;
  return {v[0] / length, v[1] / length, v[2] / length};
}

// The model as GL vertices and triangles (polygons as fans). Per-face modes give each face its
// own corners, carrying the face's normal; the others share a vertex between the faces that use
// the same position, normal and texture coordinates, as an indexed mesh would.
Geometry loadGeometry(const std::string& path, Mode mode) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // the Newell normal is the whole polygon's
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) fail(path + ": " + reader.Error());
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const auto position = [&](int i) {
    const double* p = &attrib.vertices[size_t(3 * i)];
    return Vec3d{p[0], p[1], p[2]};
  };
  const bool hasNormals = !attrib.normals.empty();
  Geometry g;
  g.perFace = mode == Mode::Flat || (mode == Mode::Normal && !hasNormals);
  const bool smooth = (mode == Mode::Phong || mode == Mode::Texture) && !hasNormals;

  // Each face's corners and Newell sum (ShadingModel.cpp: its normal times twice its area).
  std::vector<std::vector<tinyobj::index_t>> faces;
  std::vector<Vec3d> sums;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    auto corner = shape.mesh.indices.begin();
    for (const unsigned int n : shape.mesh.num_face_vertices) {
      faces.emplace_back(corner, corner + n);
      corner += n;
      Vec3d sum{0, 0, 0};
      for (unsigned int i = 0; i < n; ++i) {
        const Vec3d p = position(faces.back()[i].vertex_index);
        const Vec3d q = position(faces.back()[(i + 1) % n].vertex_index);
        sum[0] += (p[1] - q[1]) * (p[2] + q[2]);
        sum[1] += (p[2] - q[2]) * (p[0] + q[0]);
        sum[2] += (p[0] - q[0]) * (p[1] + q[1]);
      }
      sums.push_back(sum);
    }
  }
  // Smooth normals (SurfaceSetup.cpp): per position, the normalized sum of the Newell sums of
  // the faces around it, i.e. area-weighted.
  std::vector<Vec3d> smoothNormals;
  if (smooth) {
    smoothNormals.assign(attrib.vertices.size() / 3, Vec3d{0, 0, 0});
    for (size_t f = 0; f < faces.size(); ++f)
      for (const tinyobj::index_t& c : faces[f])
        for (int k = 0; k < 3; ++k) smoothNormals[size_t(c.vertex_index)][k] += sums[f][k];
    for (Vec3d& n : smoothNormals) n = normalized(n, {0, 0, 1});
  }

  std::map<std::array<int, 3>, GLuint> shared;  // (position, vn or -1 for smooth, vt) -> vertex
  for (size_t f = 0; f < faces.size(); ++f) {
    bool allNormals = hasNormals, allUvs = !attrib.texcoords.empty();
    Vec3d centroid{0, 0, 0};
    for (const tinyobj::index_t& c : faces[f]) {
      allNormals = allNormals && c.normal_index >= 0;
      allUvs = allUvs && c.texcoord_index >= 0;
      for (int k = 0; k < 3; ++k) centroid[k] += position(c.vertex_index)[k] / faces[f].size();
    }
    // The normal a corner carries, as SurfaceSetup chooses it: the vn of a face that has them
    // all, else the smooth normal (phong, texture), else the face's (never shared).
    const bool faceNormal = g.perFace || (!allNormals && !smooth);
    std::vector<GLuint> corners;
    for (const tinyobj::index_t& c : faces[f]) {
      const std::array<int, 3> key{c.vertex_index, allNormals ? c.normal_index : -1,
                                   allUvs ? c.texcoord_index : -1};
      const auto found = faceNormal ? shared.end() : shared.find(key);
      if (found != shared.end()) {
        corners.push_back(found->second);
        continue;
      }
      const Vec3d n = faceNormal   ? normalized(sums[f], {0, 0, 0})
                      : allNormals ? Vec3d{attrib.normals[size_t(3 * c.normal_index)],
                                           attrib.normals[size_t(3 * c.normal_index + 1)],
                                           attrib.normals[size_t(3 * c.normal_index + 2)]}
                                   : smoothNormals[size_t(c.vertex_index)];
      Vertex v{};
      for (int k = 0; k < 3; ++k) {
        v.position[k] = float(position(c.vertex_index)[k]);
        v.normal[k] = float(n[k]);
        v.centroid[k] = float(centroid[k]);
      }
      for (int k = 0; k < 2 && allUvs; ++k)
        v.uv[k] = float(attrib.texcoords[size_t(2 * c.texcoord_index + k)]);
      corners.push_back(GLuint(g.vertices.size()));
      if (!faceNormal) shared.emplace(key, corners.back());
      g.vertices.push_back(v);
    }
    for (size_t j = 1; j + 1 < corners.size(); ++j)
      g.indices.insert(g.indices.end(), {corners[0], corners[j], corners[j + 1]});
  }
  // One draw call, so one material: the first one's (the reference scenes have none).
  if (!reader.GetMaterials().empty()) {
    const tinyobj::material_t& m = reader.GetMaterials()[0];
    std::copy(m.diffuse, m.diffuse + 3, g.base);
    if (!m.diffuse_texname.empty())
      g.texture = (std::filesystem::path(path).parent_path() / m.diffuse_texname).string();
    if (reader.GetMaterials().size() > 1)
      std::fprintf(stderr, "llvmpipe-ref: several materials: the first one's Kd for all\n");
  }
  return g;
}

// One vertex and one fragment shader for every mode, specialized by the defines before them
// (buildProgram). They compute SurfaceSample.hpp's per-sample modes and FaceColors.cpp's
// per-face ones. GL's perspective-correct `smooth` varyings interpolate as zrender's ray-plane
// weights do, and GL samples at pixel centres as zrender does.
const char* const kVertexShader = R"(
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 3) in vec3 faceCentroid;  // ("centroid" is a GLSL keyword)
uniform mat4 modelView;  // rigid: its 3x3 part turns normals, as zrender's transformDirection
uniform mat4 projection;
#if PER_FACE
flat out vec3 faceColor;  // every corner of a face computes the same
#else
out vec3 viewPosition;
out vec3 viewNormal;
out vec2 texCoord;
#endif

vec3 safeNormalize(vec3 v) {
  float length2 = dot(v, v);
  return length2 > 0.0 ? v * inversesqrt(length2) : vec3(0.0, 0.0, 1.0);
}

void main() {
  vec4 p = modelView * vec4(position, 1.0);
  gl_Position = projection * p;
  vec3 n = mat3(modelView) * normal;
#if FLAT
  // Gray |Lambert term| of the face normal for a light at the eye, seen from the centroid.
  vec3 c = (modelView * vec4(faceCentroid, 1.0)).xyz;
  faceColor = vec3(abs(dot(n, safeNormalize(-c))));
#elif PER_FACE
  faceColor = (n + 1.0) * 0.5;  // normal mode on a model without vn: the face normal's color
#else
  viewPosition = p.xyz;
  viewNormal = safeNormalize(n);
  texCoord = uv;
#endif
}
)";

const char* const kFragmentShader = R"(
#if PER_FACE
flat in vec3 faceColor;
#else
in vec3 viewPosition;
in vec3 viewNormal;
in vec2 texCoord;
#endif
uniform vec3 baseColor;  // 0..1
uniform sampler2D diffuseMap;
uniform bool textured;
out vec4 fragColor;  // RGBA8: GL rounds 255 times the color to a byte, as zrender's + 0.5

vec3 safeNormalize(vec3 v) {
  float length2 = dot(v, v);
  return length2 > 0.0 ? v * inversesqrt(length2) : vec3(0.0, 0.0, 1.0);
}

void main() {
#if PER_FACE
  fragColor = vec4(faceColor, 1.0);
#elif NORMAL
  fragColor = vec4(safeNormalize(viewNormal) * 0.5 + 0.5, 1.0);
#else
  // Light at the eye: the direction to it is minus the view-space position.
  float diffuse = max(dot(safeNormalize(viewNormal), normalize(-viewPosition)), 0.0);
  // White specular 0.3 of diffuse^64 (light, eye and half vector coincide), which zrender
  // leaves out below 0.5 (there under 2^-64) and takes by six squarings.
  float specular = 0.0;
  if (diffuse >= 0.5) {
    specular = diffuse;
    for (int k = 0; k < 6; ++k) specular *= specular;
  }
  vec3 base = textured ? texture(diffuseMap, texCoord).rgb : baseColor;
  fragColor = vec4(base * (0.1 + 0.9 * diffuse) + 0.3 * specular, 1.0);  // ambient 0.1
#endif
}
)";

GLuint buildProgram(Mode mode, bool perFace) {
  const std::string defines = std::string("#version 330 core\n#define PER_FACE ") +
                              (perFace ? "1" : "0") + "\n#define FLAT " +
                              (mode == Mode::Flat ? "1" : "0") + "\n#define NORMAL " +
                              (mode == Mode::Normal ? "1" : "0") + "\n";
  const GLuint program = glCreateProgram();
  char log[4096] = "";
  GLint ok = 0;
  for (const auto& [type, source] : {std::pair(GL_VERTEX_SHADER, kVertexShader),
                                     std::pair(GL_FRAGMENT_SHADER, kFragmentShader)}) {
    const GLuint shader = glCreateShader(type);
    const char* texts[] = {defines.c_str(), source};
    glShaderSource(shader, 2, texts, nullptr);
    glCompileShader(shader);
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    if (!ok) fail(std::string("shader: ") + log);
    glAttachShader(program, shader);
  }
  glLinkProgram(program);
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  glGetProgramInfoLog(program, sizeof log, nullptr, log);
  if (!ok) fail(std::string("program: ") + log);
  return program;
}

// The texture as zrender samples it: bilinear, wrapping, no mipmaps. Its rows go up from the
// image's bottom row, so that t is the OBJ's v (v = 0 the bottom row).
void uploadTexture(const std::string& path) {
  cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);  // 8-bit BGR
  if (image.empty()) fail(path + ": cannot read the texture");
  cv::flip(image, image, 0);
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.cols, image.rows, 0, GL_BGR, GL_UNSIGNED_BYTE,
               image.ptr());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

// The FBO's color image as zrender writes it: row 0 at the top, BGR for OpenCV.
void writeImage(const std::string& path, int width, int height) {
  cv::Mat rgba(height, width, CV_8UC4), bgr;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.ptr());
  cv::cvtColor(rgba, bgr, cv::COLOR_RGBA2BGR);
  cv::flip(bgr, bgr, 0);  // GL's row 0 is the bottom
  if (!cv::imwrite(path, bgr)) fail(path + ": cannot write the image");
}

int run(const Options& options) {
  const Camera camera = readCamera(options.cameras);
  const int width = options.width ? options.width : camera.width;
  const int height = options.height ? options.height : camera.height;
  if (width <= 0 || height <= 0) fail("no image size: give --width and --height");

  // OSMesa picks its Gallium driver (llvmpipe or softpipe) when the context is made.
  setenv("GALLIUM_DRIVER", "llvmpipe", 0);
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context) fail("OSMesaCreateContextAttribs: no GL 3.3 core context");
  // The context's own buffer only makes it current; the frames go to the framebuffer object.
  std::vector<unsigned char> unused(16 * 16 * 4);
  if (!OSMesaMakeCurrent(context, unused.data(), GL_UNSIGNED_BYTE, 16, 16))
    fail("OSMesaMakeCurrent failed");
  std::fprintf(stderr, "GL_RENDERER: %s\nGL_VERSION: %s\n", glGetString(GL_RENDERER),
               glGetString(GL_VERSION));

  GLuint framebuffer = 0, renderbuffers[2] = {0, 0};
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glGenRenderbuffers(2, renderbuffers);
  // 32-bit float depth, as zrender's buffer holds it (24 bits gave the same images and times).
  const GLenum formats[2] = {GL_RGBA8, GL_DEPTH_COMPONENT32F};
  const GLenum attachments[2] = {GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT};
  for (int i = 0; i < 2; ++i) {
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[i]);
    glRenderbufferStorage(GL_RENDERBUFFER, formats[i], width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachments[i], GL_RENDERBUFFER, renderbuffers[i]);
  }
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    fail("framebuffer incomplete");
  glViewport(0, 0, width, height);

  const Geometry geometry = loadGeometry(options.model, options.mode);
  const GLuint program = buildProgram(options.mode, geometry.perFace);
  glUseProgram(program);
  const auto uniform = [&](const char* name) { return glGetUniformLocation(program, name); };
  glUniformMatrix4fv(uniform("modelView"), 1, GL_FALSE, camera.view.data());  // model: identity
  glUniformMatrix4fv(uniform("projection"), 1, GL_FALSE, camera.projection.data());
  glUniform3fv(uniform("baseColor"), 1, geometry.base);
  const std::string texture = options.texture.empty() ? geometry.texture : options.texture;
  const bool textured = options.mode == Mode::Texture && !texture.empty();
  if (textured) uploadTexture(texture);  // unit 0, diffuseMap's default
  glUniform1i(uniform("textured"), textured);

  // The vertices and indices go to GL buffers once, before the timed frames.
  GLuint vertexArray = 0, buffers[2] = {0, 0};
  glGenVertexArrays(1, &vertexArray);
  glBindVertexArray(vertexArray);
  glGenBuffers(2, buffers);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(geometry.vertices.size() * sizeof(Vertex)),
               geometry.vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(geometry.indices.size() * sizeof(GLuint)),
               geometry.indices.data(), GL_STATIC_DRAW);
  const auto attribute = [](GLuint location, GLint size, size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offset));
  };
  attribute(0, 3, offsetof(Vertex, position));
  attribute(1, 3, offsetof(Vertex, normal));
  if (textured) attribute(2, 2, offsetof(Vertex, uv));
  if (options.mode == Mode::Flat) attribute(3, 3, offsetof(Vertex, centroid));

  // zrender's defaults: back faces culled (counter-clockwise front faces), the nearer depth
  // wins, a black background (settings' "background").
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClearDepth(1.0);
  const auto drawFrame = [&]() {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, GLsizei(geometry.indices.size()), GL_UNSIGNED_INT, nullptr);
    glFinish();
  };
  drawFrame();  // untimed: llvmpipe compiles its shader variants (LLVM) at the first draw
  std::vector<double> ms;
  for (int i = 0; i < options.repeat; ++i) {
    const auto start = std::chrono::steady_clock::now();
    drawFrame();
    const auto end = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
  }
  if (glGetError() != GL_NO_ERROR) fail("a GL call failed");
  if (!options.output.empty()) writeImage(options.output, width, height);
  OSMesaDestroyContext(context);

  std::sort(ms.begin(), ms.end());
  const size_t n = ms.size();
  const double median = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
  // LP_NUM_THREADS as a number when it is one, else as a string ("default" when unset).
  const char* lpThreads = std::getenv("LP_NUM_THREADS");
  std::string threads = lpThreads ? lpThreads : "default";
  if (threads.empty() || threads.find_first_not_of("0123456789") != std::string::npos)
    threads = "\"" + threads + "\"";
  std::printf(
      "{\"mode\":\"%s\",\"frame_ms\":%.3f,\"frame_ms_min\":%.3f,\"repeat\":%d,"
      "\"threads\":%s,\"width\":%d,\"height\":%d}\n",
      kModeNames[int(options.mode)], median, ms[0], options.repeat, threads.c_str(), width, height);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parseOptions(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "llvmpipe-ref: %s\n", e.what());
    return 2;
  }
}
