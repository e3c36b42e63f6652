#include "zrender/shading/Shader.hpp"

#include <algorithm>
#include <cstring>

#include "zrender/shading/PixelRows.hpp"
#include "zrender/shading/ShadingModel.hpp"

namespace zrender {

namespace {

// Writes the pixels of rows [firstRow, endRow) of `color` (8-bit BGR, the size of `fb`) as
// colorOf(key) (0x00RRGGBB).
template <typename ColorOf>
void shadeRows(const FrameBuffer& fb, int firstRow, int endRow, uint32_t background, cv::Mat& color,
               ColorOf colorOf) {
  const int width = fb.width();
  const uint32_t backgroundWords[3] = {background | background << 24,
                                       background >> 8 | background << 16,
                                       background >> 16 | background << 8};
  for (int y = firstRow; y < endRow; ++y) {
    uint8_t* out = color.ptr(y);
    const DepthKey* row = fb.row(y);
    // Four pixels (12 bytes: B, G, R each) as three separate 4-byte stores, then the rest one
    // by one. Measured: 4-byte stores beat one 8-byte and one 4-byte store by 3x here. Four
    // background pixels in a row (most of an image, in long runs) skip the look-ups.
    int x = 0;
    for (; x + 4 <= width; x += 4) {
      const uint32_t ids =
          keyFaceId(row[x]) & keyFaceId(row[x + 1]) & keyFaceId(row[x + 2]) & keyFaceId(row[x + 3]);
      if (ids == kBackgroundId) {
        for (int i = 0; i < 3; ++i) std::memcpy(out + 3 * x + 4 * i, &backgroundWords[i], 4);
        continue;
      }
      const uint32_t c0 = colorOf(row[x]), c1 = colorOf(row[x + 1]);
      const uint32_t c2 = colorOf(row[x + 2]), c3 = colorOf(row[x + 3]);
      const uint32_t words[3] = {c0 | c1 << 24, c1 >> 8 | c2 << 16, c2 >> 16 | c3 << 8};
      for (int i = 0; i < 3; ++i) std::memcpy(out + 3 * x + 4 * i, &words[i], 4);
    }
    for (; x < width; ++x) {
      const uint32_t c = colorOf(row[x]);
      out[3 * x + 0] = uint8_t(c);
      out[3 * x + 1] = uint8_t(c >> 8);
      out[3 * x + 2] = uint8_t(c >> 16);
    }
  }
}

// shadeRows with one color per face, colorOfFace(id) (0x00RRGGBB), asked once per run of a
// face's pixels along a row: a face usually covers a few pixels in a row.
template <typename ColorOfFace>
void shadeFaceRuns(const FrameBuffer& fb, int firstRow, int endRow, uint32_t background,
                   cv::Mat& color, ColorOfFace colorOfFace) {
  uint32_t lastId = kBackgroundId, lastColor = background;
  shadeRows(fb, firstRow, endRow, background, color, [&](DepthKey key) {
    const uint32_t id = keyFaceId(key);
    if (id == lastId) return lastColor;
    lastId = id;
    return lastColor = id == kBackgroundId ? background : colorOfFace(id);
  });
}

}  // namespace

Shader::Shader(const Scene& scene, ShadingMode mode) : scene_(scene), mode_(mode) {
  const bool perSample = mode == ShadingMode::Phong || mode == ShadingMode::Texture ||
                         (mode == ShadingMode::Normal && scene.mesh->hasNormals());
  if (perSample)
    surface_.emplace(scene, mode);
  else if (mode != ShadingMode::Depth)
    faceColors_.emplace(scene, mode);
  surfaceRow_ = surfaceRow();
  surfaceBgrRow_ = surfaceBgrRow();
  packBgr_ = packBgr();
}

void Shader::begin(ShadingFrame& frame, const FrameBuffer& fb, const Camera& camera, int scale,
                   cv::Mat& color, const FrameGeometry* geometry, const Threads* threads) {
  frame.fb = &fb;
  frame.color = &color;
  frame.threads = threads;
  frame.scale = scale;
  frame.shadedRows = 0;
  color.create(fb.height() / scale, fb.width() / scale, CV_8UC3);
  frame.modelView.clear();
  for (uint32_t k = 0; k < scene_.instanceCount(); ++k)
    frame.modelView.push_back(camera.view * scene_.modelMatrix(k));
  // An id image's background is id 0, whatever the scene's background color.
  const auto& bg = scene_.settings.background;
  frame.background = mode_ == ShadingMode::Id
                         ? 0
                         : (uint32_t(bg[0]) << 16) | (uint32_t(bg[1]) << 8) | uint32_t(bg[2]);
  frame.faces = geometry ? FaceParts{geometry} : FaceParts();
  if (faceColors_) faceColors_->begin(frame.modelView, frame.background, frame.faces);
  if (surface_) surface_->begin(frame.modelView, camera, fb.width(), fb.height());
  frame.perFace = scale == 1 && faceColors_;
  frame.lookup = FaceColors::Lookup::OnSight;
  frame.earlyShading = false;
  frame.rowDone.assign(size_t(color.rows), 0);
}

void Shader::findDepthRange(ShadingFrame& frame) const {
  // The range of each row of samples, then of them all: the same whatever the threads.
  const FrameBuffer& fb = *frame.fb;
  const size_t width = size_t(fb.width()), rows = size_t(fb.height());
  std::vector<float> lo(rows, 1.0f), hi(rows, 0.0f);
  const auto rangeOfRows = [&](size_t b, size_t e) {
    for (size_t y = b; y < e; ++y) {
      const DepthKey* row = fb.data() + y * width;
      for (size_t x = 0; x < width; ++x) {
        if (keyFaceId(row[x]) == kBackgroundId) continue;
        const float d = keyDepth(row[x]);
        lo[y] = std::min(lo[y], d);
        hi[y] = std::max(hi[y], d);
      }
    }
  };
  if (frame.parallel())
    frame.threads->forRanges(rows, 16, rangeOfRows);
  else
    rangeOfRows(0, rows);
  const float depthLo = rows ? *std::min_element(lo.begin(), lo.end()) : 1.0f;
  const float depthHi = rows ? *std::max_element(hi.begin(), hi.end()) : 0.0f;
  frame.depthLo = depthLo;
  frame.depthRange = depthHi > depthLo ? double(depthHi) - depthLo : 1.0;
}

bool Shader::prepareFaces(ShadingFrame& frame, bool bufferFinal) {
  if (mode_ == ShadingMode::Depth) return bufferFinal;  // the range of the whole frame
  const Threads& threads = *frame.threads;
  const size_t samples = frame.fb->size();
  if (faceColors_) frame.lookup = faceColors_->prepare(samples, &threads);
  if (surface_) {
    if (frame.faces.empty() ? surface_->setUpAll(samples)
                            : surface_->setUpFaces(frame.faces, samples, &threads))
      return true;
    if (!bufferFinal) return false;
    surface_->setUpVisible(*frame.fb, frame.faces, threads);
  }
  return true;
}

void Shader::facesGathered(ShadingFrame& frame, const FaceParts& faces) {
  if (!frame.parallel()) return;  // faces are colored on sight
  frame.faces = faces;
  if (faceColors_) faceColors_->begin(frame.modelView, frame.background, frame.faces);
  frame.earlyShading = prepareFaces(frame, false);
}

void Shader::rowsDone(ShadingFrame& frame, int first, int end) {
  const int scale = frame.scale, rows = frame.color->rows;
  if (!frame.parallel()) {
    // Depth mode stretches over the depths of the whole frame: it waits for finish().
    if (mode_ != ShadingMode::Depth) shadePixelRows(frame, std::min(end / scale, rows));
    return;
  }
  if (!frame.earlyShading) return;
  const int firstRow = (first + scale - 1) / scale, endRow = std::min(end / scale, rows);
  if (firstRow >= endRow) return;
  std::vector<uint32_t> rowColors;
  paintRows(frame, firstRow, endRow, rowColors, true);
  std::fill(frame.rowDone.begin() + firstRow, frame.rowDone.begin() + endRow, uint8_t(1));
}

void Shader::finish(ShadingFrame& frame) {
  if (mode_ == ShadingMode::Depth) findDepthRange(frame);
  if (!frame.parallel()) {
    shadePixelRows(frame, frame.color->rows);
    return;
  }
  // Every face that can be in the buffer is set up before the rows are shared out, so that
  // coloring them writes nothing but the image.
  prepareFaces(frame, true);
  frame.threads->forRanges(frame.rowDone.size(), 8, [&](size_t b, size_t e) {
    std::vector<uint32_t> rowColors;
    for (size_t y = b; y < e; ++y)
      if (!frame.rowDone[y]) paintRows(frame, int(y), int(y) + 1, rowColors, true);
  });
  frame.shadedRows = frame.color->rows;
}

void Shader::shade(const FrameBuffer& fb, const Camera& camera, int scale, cv::Mat& color) {
  ShadingFrame frame;
  begin(frame, fb, camera, scale, color, nullptr);
  finish(frame);
}

uint32_t Shader::sampleColor(const ShadingFrame& frame, DepthKey key, bool shared) {
  const uint32_t id = keyFaceId(key);
  if (id == kBackgroundId) return frame.background;
  if (mode_ == ShadingMode::Depth) {
    // Near white, far black, stretched over the depths present in the frame.
    const double g = 1.0 - (double(keyDepth(key)) - frame.depthLo) / frame.depthRange;
    return packRgb(g, g, g);
  }
  return shared ? sharedFaceColor(frame, id) : faceColors_->color(id);
}

uint32_t Shader::sharedFaceColor(const ShadingFrame& frame, uint32_t id) const {
  const uint32_t* table = faceColors_->table();
  switch (frame.lookup) {
    case FaceColors::Lookup::ById:
      return table[size_t(id) + 1];
    case FaceColors::Lookup::ByMeshFace:
      return table[id % uint32_t(scene_.mesh->faceCount())];
    default:
      return faceColors_->uncachedColor(id);
  }
}

void Shader::colorSampleRow(const ShadingFrame& frame, int y, uint32_t* out, bool shared) {
  const DepthKey* row = frame.fb->row(y);
  const int width = frame.fb->width();
  if (!surface_) {
    for (int x = 0; x < width; ++x) out[x] = sampleColor(frame, row[x], shared);
    return;
  }
  surfaceRow_(*surface_, row, width, y, frame.background, out);
}

void Shader::shadePixelRows(ShadingFrame& frame, int endRow) {
  const int firstRow = frame.shadedRows;
  if (endRow <= firstRow) return;
  frame.shadedRows = endRow;
  if (frame.perFace) frame.lookup = faceColors_->prepare(frame.fb->size());
  if (surface_ && !frame.faces.empty()) surface_->setUpFaces(frame.faces, frame.fb->size());
  paintRows(frame, firstRow, endRow, frame.rowColors, false);
}

void Shader::paintRows(const ShadingFrame& frame, int firstRow, int endRow,
                       std::vector<uint32_t>& rowColors, bool shared) {
  const FrameBuffer& fb = *frame.fb;
  cv::Mat& color = *frame.color;
  const uint32_t background = frame.background;
  if (frame.perFace) {
    const uint32_t* table = faceColors_->table();
    if (frame.lookup == FaceColors::Lookup::ById) {
      shadeRows(fb, firstRow, endRow, background, color,
                [table](DepthKey key) { return table[uint32_t(keyFaceId(key) + 1u)]; });
    } else if (frame.lookup == FaceColors::Lookup::ByMeshFace) {
      const uint32_t meshFaces = uint32_t(scene_.mesh->faceCount());
      shadeFaceRuns(fb, firstRow, endRow, background, color,
                    [&](uint32_t id) { return table[id % meshFaces]; });
    } else if (shared) {
      shadeFaceRuns(fb, firstRow, endRow, background, color,
                    [&](uint32_t id) { return faceColors_->uncachedColor(id); });
    } else {
      shadeFaceRuns(fb, firstRow, endRow, background, color,
                    [&](uint32_t id) { return faceColors_->color(id); });
    }
    return;
  }

  const int width = color.cols;
  rowColors.resize(2 * (size_t(fb.width()) + 16));  // 16: room for a last block past a row
  uint32_t* colors0 = rowColors.data();
  uint32_t* colors1 = colors0 + fb.width() + 16;
  for (int y = firstRow; y < endRow; ++y) {
    uint8_t* out = color.ptr(y);
    if (frame.scale == 1 && surface_ && surfaceBgrRow_) {
      surfaceBgrRow_(*surface_, fb.row(y), fb.width(), y, background, out);
    } else if (frame.scale == 1) {
      colorSampleRow(frame, y, colors0, shared);
      packBgr_(colors0, width, out);
    } else if (mode_ == ShadingMode::Id) {
      // A mean of ids is no face's id: an id image holds each pixel's nearest sample, as
      // --ids does (docs/design.md: Faces, ids and shading over the MSAA mean of Rasterization
      // rules).
      const DepthKey* r0 = fb.row(2 * y);
      const DepthKey* r1 = fb.row(2 * y + 1);
      for (int x = 0; x < width; ++x) {
        const uint32_t c = sampleColor(
            frame, std::min({r0[2 * x], r0[2 * x + 1], r1[2 * x], r1[2 * x + 1]}), shared);
        out[3 * x + 0] = uint8_t(c);
        out[3 * x + 1] = uint8_t(c >> 8);
        out[3 * x + 2] = uint8_t(c >> 16);
      }
    } else {
      colorSampleRow(frame, 2 * y, colors0, shared);
      colorSampleRow(frame, 2 * y + 1, colors1, shared);
      for (int x = 0; x < width; ++x) {
        const uint32_t cs[4] = {colors0[2 * x], colors0[2 * x + 1], colors1[2 * x],
                                colors1[2 * x + 1]};
        uint32_t sum[3] = {0, 0, 0};
        for (uint32_t c : cs) {
          sum[0] += c & 0xFF;
          sum[1] += (c >> 8) & 0xFF;
          sum[2] += (c >> 16) & 0xFF;
        }
        // The rounded mean of the four samples, background included (docs/design.md,
        // Rasterization rules).
        for (int i = 0; i < 3; ++i) out[3 * x + i] = uint8_t((sum[i] + 2) / 4);
      }
    }
  }
}

}  // namespace zrender
