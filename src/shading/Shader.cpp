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

void Shader::begin(const FrameBuffer& fb, const Camera& camera, int scale, cv::Mat& color,
                   const FrameGeometry* geometry) {
  fb_ = &fb;
  color_ = &color;
  scale_ = scale;
  shadedRows_ = 0;
  color.create(fb.height() / scale, fb.width() / scale, CV_8UC3);
  modelView_.clear();
  for (uint32_t k = 0; k < scene_.instanceCount(); ++k)
    modelView_.push_back(camera.view * scene_.modelMatrix(k));
  // An id image's background is id 0, whatever the scene's background color.
  const auto& bg = scene_.settings.background;
  background_ = mode_ == ShadingMode::Id
                    ? 0
                    : (uint32_t(bg[0]) << 16) | (uint32_t(bg[1]) << 8) | uint32_t(bg[2]);
  faces_ = geometry ? FaceParts{geometry} : FaceParts();
  if (faceColors_) faceColors_->begin(modelView_, background_, faces_);
  if (surface_) surface_->begin(modelView_, camera, fb.width(), fb.height());
  perFace_ = scale == 1 && faceColors_;
  earlyShading_ = false;
  rowDone_.assign(size_t(color.rows), 0);
}

void Shader::rowsFinal(int sampleRows) {
  // Depth mode stretches over the depths of the whole frame: it waits for finish().
  if (mode_ == ShadingMode::Depth) return;
  shadePixelRows(std::min(sampleRows / scale_, color_->rows));
}

void Shader::findDepthRange(size_t begin, size_t end, float& lo, float& hi) const {
  lo = 1.0f;
  hi = 0.0f;
  for (size_t i = begin; i < end; ++i) {
    if (keyFaceId(fb_->data()[i]) == kBackgroundId) continue;
    const float d = keyDepth(fb_->data()[i]);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
}

void Shader::finish() {
  if (mode_ == ShadingMode::Depth) {
    float depthHi = 0.0f;
    findDepthRange(0, fb_->size(), depthLo_, depthHi);
    depthRange_ = depthHi > depthLo_ ? double(depthHi) - depthLo_ : 1.0;
  }
  shadePixelRows(color_->rows);
}

bool Shader::prepareFaces(const Threads& threads, bool bufferFinal) {
  if (mode_ == ShadingMode::Depth) return bufferFinal;  // the range of the whole frame
  if (faceColors_) lookup_ = faceColors_->prepare(fb_->size(), &threads);
  if (surface_) {
    if (faces_.empty() ? surface_->setUpAll(fb_->size())
                       : surface_->setUpFaces(faces_, fb_->size()))
      return true;
    if (!bufferFinal) return false;
    surface_->setUpVisible(*fb_, faces_, threads);
  }
  return true;
}

void Shader::useFaces(const FaceParts& faces) {
  faces_ = faces;
  if (faceColors_) faceColors_->begin(modelView_, background_, faces_);
}

void Shader::prepareRows(const Threads& threads) {
  earlyShading_ = prepareFaces(threads, false);
}

void Shader::rowsReady(int first, int end) {
  if (!earlyShading_) return;
  const int firstRow = (first + scale_ - 1) / scale_, endRow = std::min(end / scale_, color_->rows);
  if (firstRow >= endRow) return;
  std::vector<uint32_t> rowColors;
  paintRows(firstRow, endRow, rowColors, true);
  std::fill(rowDone_.begin() + firstRow, rowDone_.begin() + endRow, uint8_t(1));
}

void Shader::finish(const Threads& threads) {
  if (!threads.parallel()) {
    finish();
    return;
  }
  if (mode_ == ShadingMode::Depth) {
    // The range of each row of samples, then of them all: the same whatever the threads.
    const size_t width = size_t(fb_->width()), rows = size_t(fb_->height());
    std::vector<float> lo(rows), hi(rows);
    threads.forRanges(rows, 16, [&](size_t b, size_t e) {
      for (size_t y = b; y < e; ++y) findDepthRange(y * width, (y + 1) * width, lo[y], hi[y]);
    });
    depthLo_ = *std::min_element(lo.begin(), lo.end());
    const float depthHi = *std::max_element(hi.begin(), hi.end());
    depthRange_ = depthHi > depthLo_ ? double(depthHi) - depthLo_ : 1.0;
  }
  // Every face that can be in the buffer is set up before the rows are shared out, so that
  // coloring them writes nothing but the image.
  prepareFaces(threads, true);
  threads.forRanges(rowDone_.size(), 8, [&](size_t b, size_t e) {
    std::vector<uint32_t> rowColors;
    for (size_t y = b; y < e; ++y)
      if (!rowDone_[y]) paintRows(int(y), int(y) + 1, rowColors, true);
  });
  shadedRows_ = color_->rows;
}

void Shader::shade(const FrameBuffer& fb, const Camera& camera, int scale, cv::Mat& color) {
  begin(fb, camera, scale, color);
  finish();
}

uint32_t Shader::sampleColor(DepthKey key, bool shared) {
  const uint32_t id = keyFaceId(key);
  if (id == kBackgroundId) return background_;
  if (mode_ == ShadingMode::Depth) {
    // Near white, far black, stretched over the depths present in the frame.
    const double g = 1.0 - (double(keyDepth(key)) - depthLo_) / depthRange_;
    return packRgb(g, g, g);
  }
  return shared ? sharedFaceColor(id) : faceColors_->color(id);
}

uint32_t Shader::sharedFaceColor(uint32_t id) const {
  const uint32_t* table = faceColors_->table();
  switch (lookup_) {
    case FaceColors::Lookup::ById:
      return table[size_t(id) + 1];
    case FaceColors::Lookup::ByMeshFace:
      return table[id % uint32_t(scene_.mesh->faceCount())];
    default:
      return faceColors_->uncachedColor(id);
  }
}

void Shader::colorSampleRow(int y, uint32_t* out, bool shared) {
  const DepthKey* row = fb_->row(y);
  const int width = fb_->width();
  if (!surface_) {
    for (int x = 0; x < width; ++x) out[x] = sampleColor(row[x], shared);
    return;
  }
  surfaceRow_(*surface_, row, width, y, background_, out);
}

void Shader::shadePixelRows(int endRow) {
  const int firstRow = shadedRows_;
  if (endRow <= firstRow) return;
  shadedRows_ = endRow;
  if (perFace_) lookup_ = faceColors_->prepare(fb_->size());
  if (surface_ && !faces_.empty()) surface_->setUpFaces(faces_, fb_->size());
  paintRows(firstRow, endRow, rowColors_, false);
}

void Shader::paintRows(int firstRow, int endRow, std::vector<uint32_t>& rowColors, bool shared) {
  const FrameBuffer& fb = *fb_;
  cv::Mat& color = *color_;
  if (perFace_) {
    const uint32_t* table = faceColors_->table();
    if (lookup_ == FaceColors::Lookup::ById) {
      shadeRows(fb, firstRow, endRow, background_, color,
                [table](DepthKey key) { return table[uint32_t(keyFaceId(key) + 1u)]; });
    } else if (lookup_ == FaceColors::Lookup::ByMeshFace) {
      const uint32_t meshFaces = uint32_t(scene_.mesh->faceCount());
      shadeFaceRuns(fb, firstRow, endRow, background_, color,
                    [&](uint32_t id) { return table[id % meshFaces]; });
    } else if (shared) {
      shadeFaceRuns(fb, firstRow, endRow, background_, color,
                    [&](uint32_t id) { return faceColors_->uncachedColor(id); });
    } else {
      shadeFaceRuns(fb, firstRow, endRow, background_, color,
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
    if (scale_ == 1 && surface_ && surfaceBgrRow_) {
      surfaceBgrRow_(*surface_, fb.row(y), fb.width(), y, background_, out);
    } else if (scale_ == 1) {
      colorSampleRow(y, colors0, shared);
      packBgr_(colors0, width, out);
    } else if (mode_ == ShadingMode::Id) {
      // A mean of ids is no face's id: an id image holds each pixel's nearest sample, as
      // --ids does (docs/design.md: Faces, ids and shading over the MSAA mean of Rasterization
      // rules).
      const DepthKey* r0 = fb.row(2 * y);
      const DepthKey* r1 = fb.row(2 * y + 1);
      for (int x = 0; x < width; ++x) {
        const uint32_t c =
            sampleColor(std::min({r0[2 * x], r0[2 * x + 1], r1[2 * x], r1[2 * x + 1]}), shared);
        out[3 * x + 0] = uint8_t(c);
        out[3 * x + 1] = uint8_t(c >> 8);
        out[3 * x + 2] = uint8_t(c >> 16);
      }
    } else {
      colorSampleRow(2 * y, colors0, shared);
      colorSampleRow(2 * y + 1, colors1, shared);
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
