#include "zrender/raster/BandOrder.hpp"

#include <algorithm>

namespace zrender {

std::vector<uint32_t> BandOrder::longestFirst(const RowBands& rows) const {
  const int height = rows.rowEnd(rows.count() - 1);
  std::vector<uint32_t> order(static_cast<size_t>(rows.count()));
  std::vector<double> ms(order.size(), 0.0);
  const bool known = rowMs_.size() == size_t(height);
  for (int b = 0; b < rows.count(); ++b) {
    order[size_t(b)] = uint32_t(b);
    if (known)
      for (int y = rows.rowBegin(b); y < rows.rowEnd(b); ++y) ms[size_t(b)] += rowMs_[size_t(y)];
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return ms[a] > ms[b]; });
  return order;
}

void BandOrder::keep(const RowBands& rows, const std::vector<double>& bandMs) {
  rowMs_.resize(size_t(rows.rowEnd(rows.count() - 1)));
  for (int b = 0; b < rows.count(); ++b) {
    const int begin = rows.rowBegin(b), end = rows.rowEnd(b);
    if (end > begin)
      std::fill(rowMs_.begin() + begin, rowMs_.begin() + end, bandMs[size_t(b)] / (end - begin));
  }
}

}  // namespace zrender
