#include "zrender/io/models/ModelFormats.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "zrender/base/Error.hpp"
#include "zrender/io/images/ImageCodecs.hpp"

namespace zrender {

const std::vector<ModelFormatInfo>& modelFormats() {
  static const std::vector<ModelFormatInfo> formats = {
      {ModelFormat::Obj, "obj", "OBJ", "Wavefront OBJ with its MTL materials", {".obj"}},
      {ModelFormat::Ply, "ply", "PLY", "Stanford PLY, ASCII or binary, vertex colors", {".ply"}},
      {ModelFormat::Stl, "stl", "STL", "STL, ASCII or binary", {".stl"}},
      {ModelFormat::Off, "off", "OFF", "Object File Format", {".off"}},
      {ModelFormat::Gltf,
       "gltf",
       "glTF",
       "glTF 2.0: .gltf with its buffers and images, or .glb",
       {".gltf", ".glb"}},
      {ModelFormat::Fbx, "fbx", "FBX", "Autodesk FBX", {".fbx"}},
      {ModelFormat::Collada, "dae", "Collada", "Collada (.dae)", {".dae"}},
      {ModelFormat::ThreeDs, "3ds", "3DS", "3D Studio", {".3ds"}},
  };
  return formats;
}

const ModelFormatInfo& modelFormatInfo(ModelFormat format) {
  for (const ModelFormatInfo& info : modelFormats()) {
    if (info.format == format) return info;
  }
  return modelFormats().front();
}

std::optional<ModelFormat> modelFormatOfPath(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  for (const ModelFormatInfo& info : modelFormats()) {
    for (const char* e : info.extensions) {
      if (ext == e) return info.format;
    }
  }
  return std::nullopt;
}

std::string modelExtensionList() {
  std::string list;
  for (const ModelFormatInfo& info : modelFormats()) {
    for (const char* e : info.extensions) list += (list.empty() ? "" : ", ") + std::string(e + 1);
  }
  return list;
}

uint32_t littleEndian32(std::string_view bytes, size_t at) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = v << 8 | uint8_t(bytes[at + size_t(i)]);
  return v;
}

bool isBinaryStl(std::string_view bytes, uint64_t fileSize) {
  return fileSize >= 84 && bytes.size() >= 84 &&
         84 + 50 * uint64_t(littleEndian32(bytes, 80)) == fileSize;
}

namespace {

bool startsWith(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

std::string_view skipSpace(std::string_view s) {
  size_t i = 0;
  while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  return s.substr(i);
}

std::string_view firstWord(std::string_view s) {
  s = skipSpace(s);
  size_t i = 0;
  while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  return s.substr(0, i);
}

// OFF's header keyword: [ST][C][N][4][n]OFF, optionally followed by BINARY.
bool isOffKeyword(std::string_view w) {
  if (startsWith(w, "OFF") && (w.size() == 3 || w.substr(3) == "BINARY")) return true;
  const size_t at = w.find("OFF");
  if (at == std::string_view::npos || at == 0 || at > 5) return false;
  if (w.size() != at + 3 && w.substr(at + 3) != "BINARY") return false;
  return w.substr(0, at).find_first_not_of("STCN4n") == std::string_view::npos;
}

// Lines that start as OBJ statements do: the usual keywords, then a space.
bool looksLikeObj(std::string_view head) {
  static const char* const keywords[] = {"v ", "vn ", "vt ",     "f ",
                                         "o ", "g ",  "mtllib ", "usemtl "};
  size_t pos = 0;
  while (pos < head.size()) {
    const size_t end = std::min(head.find('\n', pos), head.size());
    const std::string_view line = skipSpace(head.substr(pos, end - pos));
    for (const char* k : keywords) {
      if (startsWith(line, k)) return true;
    }
    pos = end + 1;
  }
  return false;
}

bool isText(std::string_view head) {
  size_t control = 0;
  for (char c : head) {
    const auto u = static_cast<unsigned char>(c);
    if (u == 0) return false;
    if (u < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v') ++control;
  }
  return control * 100 <= head.size();
}

}  // namespace

ModelContent sniffModelContent(std::string_view head, uint64_t fileSize) {
  head = head.substr(0, kModelHeadBytes);
  if (fileSize == 0) return {std::nullopt, "an empty file"};
  // Signatures first: binary files whose first bytes are fixed.
  struct Signature {
    std::string_view bytes;
    const char* looksLike;
  };
  static const Signature others[] = {
      {"\x89PNG\r\n\x1a\n", "a PNG image"},
      {"\xFF\xD8\xFF", "a JPEG image"},
      {"GIF8", "a GIF image"},
      {std::string_view("II*\0", 4), "a TIFF image"},
      {std::string_view("MM\0*", 4), "a TIFF image"},
      {"%PDF-", "a PDF document"},
      {"PK\x03\x04", "a ZIP archive"},
      {"\x1F\x8B", "gzip-compressed data"},
      {"\x7F"
       "ELF",
       "an executable"},
      {"\x76\x2F\x31\x01", "an OpenEXR image"},
  };
  for (const Signature& s : others) {
    if (startsWith(head, s.bytes)) return {std::nullopt, s.looksLike};
  }
  if (startsWith(head, "RIFF") && head.size() >= 12 && head.substr(8, 4) == "WEBP")
    return {std::nullopt, "a WebP image"};
  if (startsWith(head, "BM") && head.size() >= 6 && littleEndian32(head, 2) == fileSize)
    return {std::nullopt, "a BMP image"};
  if (startsWith(head, "glTF")) return {ModelFormat::Gltf, "a binary glTF model"};
  if (startsWith(head, "ply\n") || startsWith(head, "ply\r"))
    return {ModelFormat::Ply, "a PLY model"};
  if (startsWith(head, "Kaydara FBX Binary")) return {ModelFormat::Fbx, "an FBX model"};
  if (isBinaryStl(head, fileSize)) return {ModelFormat::Stl, "a binary STL model"};
  // 3DS: a main chunk (0x4D4D) whose length is at most the file's.
  if (head.size() >= 6 && uint8_t(head[0]) == 0x4D && uint8_t(head[1]) == 0x4D) {
    const uint32_t length = littleEndian32(head, 2);
    if (length >= 6 && length <= fileSize) return {ModelFormat::ThreeDs, "a 3DS model"};
  }
  if (!isText(head)) return {std::nullopt, "binary data"};

  // Text: by its first word or its markup.
  std::string_view text = head;
  if (startsWith(text, "\xEF\xBB\xBF")) text.remove_prefix(3);
  const std::string_view word = firstWord(text);
  if (isOffKeyword(word)) return {ModelFormat::Off, "an OFF model"};
  if (word == "solid") return {ModelFormat::Stl, "an ASCII STL model"};
  if (startsWith(skipSpace(text), "; FBX")) return {ModelFormat::Fbx, "an FBX model"};
  if (startsWith(skipSpace(text), "{")) {
    if (text.find("\"asset\"") != std::string_view::npos)
      return {ModelFormat::Gltf, "a glTF model"};
    return {std::nullopt, "JSON text"};
  }
  if (startsWith(skipSpace(text), "<")) {
    if (text.find("<COLLADA") != std::string_view::npos)
      return {ModelFormat::Collada, "a Collada model"};
    if (text.find("<svg") != std::string_view::npos) return {std::nullopt, "an SVG image"};
    return {std::nullopt, "XML or HTML text"};
  }
  if (looksLikeObj(text)) return {ModelFormat::Obj, "an OBJ model"};
  return {std::nullopt, "text"};
}

void checkModelContent(const std::string& file, ModelFormat format, std::string_view head,
                       uint64_t fileSize) {
  const ModelContent content = sniffModelContent(head, fileSize);
  bool matches = content.format == format;
  if (format == ModelFormat::Obj) {
    // Any text may be an OBJ (its reader names the first bad line); only the bytes of another
    // known kind are refused here. An empty OBJ is a model without faces.
    matches = content.format == ModelFormat::Obj || content.looksLike == "text" ||
              content.looksLike == "binary data" || content.looksLike == "an empty file";
  } else if (format == ModelFormat::Gltf && content.looksLike == "JSON text") {
    matches = true;  // glTF's "asset" may come after the first bytes; assimp reads the rest
  }
  if (matches) return;
  // "an" before the letters whose names start with a vowel sound (an OBJ, an STL, a PLY).
  const char* title = modelFormatInfo(format).title;
  const bool vowel = std::strchr("AEFHILMNORSX", title[0]) != nullptr;
  throw InputError(file + ": not " + (vowel ? "an " : "a ") + title + " file (looks like " +
                   content.looksLike + "); zrender reads: " + modelExtensionList());
}

}  // namespace zrender
