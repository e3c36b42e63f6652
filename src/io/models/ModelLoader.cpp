#include "zrender/io/models/ModelLoader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "zrender/base/AddressSpaceLimit.hpp"
#include "zrender/base/Plugin.hpp"
#include "zrender/io/files/FileText.hpp"
#include "zrender/io/images/ImageCodecs.hpp"
#include "zrender/io/models/ModelPlugin.hpp"
#include "zrender/io/models/PlyReader.hpp"
#include "zrender/io/models/StlReader.hpp"
#include "zrender/io/obj/ObjLoader.hpp"
#include "zrender/io/obj/ObjScanner.hpp"

namespace zrender {

namespace {

ModelPlugin& modelPlugin() {
  static ModelPlugin& plugin = [&]() -> ModelPlugin& {
    limitImageReads();  // the plugin decodes embedded textures with OpenCV
    return loadPlugin<ModelPlugin>("libzrender_models.so", "zrenderModelPlugin");
  }();
  return plugin;
}

// The rules every format's mesh keeps, as the OBJ reader's own checks do for OBJ.
void checkMesh(const std::string& file, const Mesh& mesh) {
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const cv::Vec3d& p = mesh.positions[i];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw InputError(file + ": NaN or infinite coordinate");
  }
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (mesh.cornerCount(f) > kMaxFaceCorners) {
      throw InputError(file + ": face " + std::to_string(f) + " has " +
                       std::to_string(mesh.cornerCount(f)) + " corners, over the " +
                       std::to_string(kMaxFaceCorners) + " zrender draws");
    }
  }
  if (mesh.faceCount() == 0) throw InputError(file + ": model has no faces");
}

// Moves `pos` past spaces, line ends and comments (# to the line's end).
void skipOffBlanks(std::string_view bytes, size_t& pos) {
  while (pos < bytes.size()) {
    if (bytes[pos] == '#') {
      pos = bytes.find('\n', pos);
    } else if (bytes[pos] == ' ' || bytes[pos] == '\t' || bytes[pos] == '\r' ||
               bytes[pos] == '\n') {
      ++pos;
    } else {
      return;
    }
  }
}

// An OFF's vertex and face counts, which assimp 5.2 reserves memory for before it reads them:
// each takes a byte of the file at least. The keyword may follow a byte order mark and blanks;
// an nOFF's dimension comes before the counts. A count is read as assimp reads it, every digit
// (leading zeros too), and kept exact up to UINT64_MAX, where it stays: assimp's own value, the
// digits taken modulo 2^32, is never larger.
void checkOffCounts(const std::string& file, std::string_view bytes) {
  size_t pos = bytes.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;  // assimp drops a UTF-8 BOM
  skipOffBlanks(bytes, pos);
  const size_t keyword = pos;
  pos = std::min(bytes.size(), bytes.find_first_of(" \t\r\n#", pos));
  const bool dimension =
      bytes.substr(keyword, pos - keyword).find("nOFF") != std::string_view::npos;
  constexpr uint64_t kMost = UINT64_MAX;
  uint64_t numbers[3] = {0, 0, 0};  // the dimension (nOFF only), the vertices, the faces
  for (int i = dimension ? 0 : 1; i < 3; ++i) {
    skipOffBlanks(bytes, pos);
    if (pos >= bytes.size()) return;  // assimp says what is missing
    for (; pos < bytes.size() && bytes[pos] >= '0' && bytes[pos] <= '9'; ++pos) {
      const uint64_t digit = uint64_t(bytes[pos] - '0');
      numbers[i] = numbers[i] > (kMost - digit) / 10 ? kMost : numbers[i] * 10 + digit;
    }
  }
  const uint64_t vertices = numbers[1], faces = numbers[2];
  if (vertices > bytes.size() || faces > bytes.size() - vertices) {
    const auto text = [&](uint64_t n) {
      return n == kMost ? std::to_string(n) + " or more" : std::to_string(n);
    };
    throw InputError(file + ": its OFF header announces " + text(vertices) + " vertices and " +
                     text(faces) + " faces, more than its " + std::to_string(bytes.size()) +
                     " bytes can hold");
  }
}

// A binary glTF's chunks lie within the file: assimp 5.2 allocates a chunk's length as its
// header says before it reads it.
void checkGlbChunks(const std::string& file, std::string_view bytes) {
  if (bytes.substr(0, 4) != "glTF") return;  // JSON
  const auto cut = [&](const std::string& what) {
    throw InputError(file + ": " + what + " (is the binary glTF cut short?)");
  };
  if (bytes.size() < 20) cut("no room for the header and a chunk");
  for (size_t at = 12; at < bytes.size();) {
    if (bytes.size() - at < 8) cut("a chunk header runs past the end");
    const uint64_t length = littleEndian32(bytes, at);
    if (length > bytes.size() - at - 8)
      cut("a chunk of " + std::to_string(length) + " bytes runs past the end");
    at += 8 + size_t(length);
  }
}

// What assimp 5.2 does not survive, refused before it reads: headers whose counts make it
// allocate more than the file could hold.
void checkForAssimp(const std::string& file, ModelFormat format, std::string_view bytes) {
  if (format == ModelFormat::Off) checkOffCounts(file, bytes);
  if (format == ModelFormat::Gltf) checkGlbChunks(file, bytes);
}

// What assimp may map while it reads a model, beyond what the process maps: 4 GiB, or 64 bytes
// per byte of the file if that is more. assimp 5.2 grows arrays without end on some damaged
// files (a Collada index list with a letter in a number took 13 GB in a minute); past the budget
// it gets std::bad_alloc, which the plugin reports in one line.
size_t assimpBudget(std::string_view bytes) {
  constexpr size_t kLeast = size_t(4) << 30;
  return std::max(kLeast, bytes.size() > SIZE_MAX / 64 ? SIZE_MAX : 64 * bytes.size());
}

Mesh readWithPlugin(std::string_view bytes, const std::string& file, ModelFormat format,
                    bool filesBeside, Warnings& warnings) {
  checkForAssimp(file, format, bytes);
  ModelPlugin& plugin = modelPlugin();  // its libraries mapped before the limit is set
  Mesh mesh;
  std::string error;
  bool read = false;
  {
    // Models are read one at a time (SceneFiles.cpp). What may run meanwhile: the start of the
    // worker threads (ThreadsStart), whose stacks are mapped at once, and the decoding of a
    // scene's `texture` key, whose image counts against the same budget.
    const AddressSpaceLimit limit(assimpBudget(bytes));
    read = plugin.read(file, bytes, format, filesBeside, mesh, warnings, error);
  }
  if (!read) {
    // assimp's reason may quote bytes of the file: escaped to one printable line.
    throw InputError(file + ": cannot read the " + modelFormatInfo(format).title +
                     " file: " + quoteName(error));
  }
  checkMesh(file, mesh);
  return mesh;
}

// The reader of each format: OBJ, PLY and STL zrender's own, the others assimp's.
Mesh readBytes(std::string_view bytes, const std::string& file, ModelFormat format,
               bool filesBeside, Warnings& warnings, const Threads* threads) {
  if (format == ModelFormat::Obj) return loadObjFromText(bytes, file, warnings, threads);
  if (format == ModelFormat::Ply || format == ModelFormat::Stl) {
    Mesh mesh = format == ModelFormat::Ply ? readPly(bytes, file) : readStl(bytes, file);
    checkMesh(file, mesh);
    return mesh;
  }
  return readWithPlugin(bytes, file, format, filesBeside, warnings);
}

}  // namespace

Mesh loadModel(const std::filesystem::path& path, Warnings& warnings, const Threads* threads) {
  const std::string file = path.string();
  const FileText bytes(file);  // first: a missing file or a device is said as such
  const std::optional<ModelFormat> format = modelFormatOfPath(path);
  if (!format) {
    const std::string ext = path.extension().string();
    throw InputError(file + ": " +
                     (ext.empty() ? std::string("no extension to tell its model format")
                                  : "unknown model format '" + ext + "'") +
                     "; zrender reads: " + modelExtensionList());
  }
  const std::string_view text = bytes.text();
  checkModelContent(file, *format, text.substr(0, kModelHeadBytes), text.size());
  return readBytes(text, file, *format, true, warnings, threads);
}

Mesh readModel(std::string_view bytes, const std::string& nameForMessages, ModelFormat format,
               Warnings& warnings) {
  checkModelContent(nameForMessages, format, bytes.substr(0, kModelHeadBytes), bytes.size());
  return readBytes(bytes, nameForMessages, format, false, warnings, nullptr);
}

}  // namespace zrender
