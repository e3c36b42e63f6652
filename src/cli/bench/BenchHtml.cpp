#include "zrender/cli/bench/BenchHtml.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "zrender/cli/bench/BenchChart.hpp"
#include "zrender/cli/bench/BenchFormats.hpp"

namespace zrender {

namespace {

std::string esc(const std::string& s) {
  return xmlEscaped(s);
}

// A scene at one size, MSAA and shading: what a picture, a chart and a counters table show.
struct Group {
  BenchKey key;  // algorithm ""
  std::vector<const BenchCell*> cells;
  const BenchPicture* picture = nullptr;
};

BenchKey withoutAlgorithm(BenchKey k) {
  k.algorithm.clear();
  return k;
}

std::vector<Group> groupsOf(const BenchRun& run) {
  std::vector<Group> groups;
  for (const BenchCell& c : run.cells) {
    const BenchKey key = withoutAlgorithm(c.key);
    auto it =
        std::find_if(groups.begin(), groups.end(), [&](const Group& g) { return g.key == key; });
    if (it == groups.end()) {
      groups.push_back(Group{key, {}, nullptr});
      it = groups.end() - 1;
    }
    it->cells.push_back(&c);
  }
  for (Group& g : groups)
    for (const BenchPicture& p : run.pictures)
      if (withoutAlgorithm(p.key) == g.key) g.picture = &p;
  return groups;
}

std::string groupTitle(const BenchKey& k) {
  return k.scene + ", " + std::to_string(k.width) + "×" + std::to_string(k.height) +
         (k.msaa > 1 ? ", MSAA " + std::to_string(k.msaa) : "") + ", " + k.shading + " shading";
}

// The value below which a `fraction` of `values` lie.
double quantile(std::vector<double> values, double fraction) {
  std::sort(values.begin(), values.end());
  return sortedQuantile(values, fraction);
}

// Ticks 1, 2 or 5 times a power of ten apart, about five across [0, top].
double tickStep(double top) {
  const double raw = std::max(top, 1e-6) / 5;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10 * power;
}

const BenchCell* cellIn(const BenchRun* run, const BenchKey& key) {
  if (!run) return nullptr;
  for (const BenchCell& c : run->cells)
    if (c.key == key) return &c;
  return nullptr;
}

// A strip and box plot of every algorithm's visibility and shading samples on one axis of ms
// from 0: a row of dots per timing, the box from the lower to the upper quartile, the median a
// line across it; the baseline's medians as hollow diamonds.
std::string groupChart(const Group& g, const BenchRun* baseline) {
  constexpr double left = 150, right = 20, top = 16, lane = 18, gap = 12, width = 680;
  double most = 0;
  for (const BenchCell* c : g.cells) {
    for (double v : c->visibility.samples) most = std::max(most, v);
    for (double v : c->shade.samples) most = std::max(most, v);
    if (const BenchCell* base = cellIn(baseline, c->key))
      most = std::max({most, base->visibility.median, base->shade.median});
  }
  const double step = tickStep(most);
  const double axisTop = std::max(step, std::ceil(most / step) * step);
  const double plot = width - left - right;
  auto x = [&](double v) { return left + plot * std::max(0.0, v) / axisTop; };
  const double height = top + double(g.cells.size()) * (2 * lane + gap) + 36;
  const double bottom = height - 30;
  std::ostringstream svg;
  svg.setf(std::ios::fixed);
  svg.precision(1);
  svg << "<svg class=\"chart\" viewBox=\"0 0 " << width << " " << height
      << "\" role=\"img\" aria-labelledby=\"chart-" << esc(g.key.text()) << "\">";
  svg << "<title id=\"chart-" << esc(g.key.text()) << "\">Visibility and shading times of "
      << g.cells.size() << " algorithms on " << esc(groupTitle(g.key))
      << ", every frame a dot, in milliseconds</title>";
  for (double t = 0; t <= axisTop + step / 2; t += step) {
    svg << "<line class=\"grid\" x1=\"" << x(t) << "\" y1=\"" << top - 4 << "\" x2=\"" << x(t)
        << "\" y2=\"" << bottom << "\"/>";
    svg << "<text class=\"tick\" x=\"" << x(t) << "\" y=\"" << bottom + 14
        << "\" text-anchor=\"middle\">" << esc(fixed(t, step < 1 ? 1 : 0)) << "</text>";
  }
  svg << "<text class=\"tick\" x=\"" << width - right << "\" y=\"" << bottom + 28
      << "\" text-anchor=\"end\">ms</text>";
  double y = top;
  for (const BenchCell* c : g.cells) {
    const std::string color = hexColor(algorithmColor(c->key.algorithm));
    const BenchCell* base = cellIn(baseline, c->key);
    svg << "<g class=\"series\" data-algorithm=\"" << esc(c->key.algorithm) << "\">";
    svg << "<text class=\"label\" x=\"8\" y=\"" << y + lane + 3 << "\">" << esc(c->key.algorithm)
        << "</text>";
    const struct {
      const char* name;
      const TimingSummary* timing;
      const TimingSummary* base;
    } lanes[] = {{"visibility", &c->visibility, base ? &base->visibility : nullptr},
                 {"shading", &c->shade, base ? &base->shade : nullptr}};
    for (const auto& l : lanes) {
      const double mid = y + lane / 2;
      const double q1 = quantile(l.timing->samples, 0.25), q3 = quantile(l.timing->samples, 0.75);
      svg << "<text class=\"lane\" x=\"" << left - 8 << "\" y=\"" << mid + 4
          << "\" text-anchor=\"end\">" << l.name << "</text>";
      svg << "<rect class=\"box\" x=\"" << x(q1) << "\" y=\"" << y + 2 << "\" width=\""
          << std::max(1.0, x(q3) - x(q1)) << "\" height=\"" << lane - 4 << "\" fill=\"" << color
          << "\" stroke=\"" << color << "\"><title>" << esc(c->key.algorithm) << " " << l.name
          << ": median " << fixed(l.timing->median, 3) << " ms, quartiles " << fixed(q1, 3)
          << " to " << fixed(q3, 3) << " ms, " << l.timing->samples.size()
          << " frames</title></rect>";
      svg << "<line class=\"median\" x1=\"" << x(l.timing->median) << "\" y1=\"" << y << "\" x2=\""
          << x(l.timing->median) << "\" y2=\"" << y + lane << "\"/>";
      for (size_t i = 0; i < l.timing->samples.size(); ++i)
        svg << "<circle class=\"sample\" cx=\"" << x(l.timing->samples[i]) << "\" cy=\""
            << mid + double(int(i % 5) - 2) * 2 << "\" r=\"2.2\" fill=\"" << color << "\"/>";
      if (l.base) {
        const double bx = x(l.base->median);
        svg << "<path class=\"baseline\" d=\"M" << bx << " " << mid - 6 << "L" << bx + 5 << " "
            << mid << "L" << bx << " " << mid + 6 << "L" << bx - 5 << " " << mid
            << "Z\"><title>baseline median " << fixed(l.base->median, 3) << " ms</title></path>";
      }
      y += lane;
    }
    svg << "</g>";
    y += gap;
  }
  svg << "<line class=\"axis\" x1=\"" << left << "\" y1=\"" << bottom << "\" x2=\"" << width - right
      << "\" y2=\"" << bottom << "\"/>";
  svg << "</svg>";
  return svg.str();
}

std::string counters(const Group& g) {
  std::ostringstream t;
  t << "<div class=\"scroll\"><table class=\"counters\"><caption>Culling counters of the last "
       "frame</caption><thead><tr>"
       "<th scope=\"col\">algorithm</th><th scope=\"col\">triangles rasterized</th>"
       "<th scope=\"col\">culled by the z-pyramid</th><th scope=\"col\">octree nodes culled / "
       "visited</th><th scope=\"col\">identical to zbuffer</th></tr></thead><tbody>";
  for (const BenchCell* c : g.cells)
    t << "<tr><th scope=\"row\">" << esc(c->key.algorithm) << "</th><td>"
      << c->stats["triangles_rasterized"].asUInt64() << "</td><td>"
      << c->stats["triangles_hzb_culled"].asUInt64() << "</td><td>"
      << c->stats["octree_nodes_culled"].asUInt64() << " / "
      << c->stats["octree_nodes_visited"].asUInt64() << "</td><td>"
      << (c->identical ? "yes" : "<strong>no</strong>") << "</td></tr>";
  t << "</tbody></table></div>";
  return t.str();
}

// A table cell sorted by `value`, showing `text`.
std::string numberCell(double value, const std::string& text) {
  return "<td data-value=\"" + fixed(value, 4) + "\">" + esc(text) + "</td>";
}

std::string cellsTable(const BenchRun& run, const BenchComparison* comparison) {
  const bool perThread = run.threads > 1;
  std::vector<std::string> heads = {
      "scene",      "size",          "algorithm",  "frame ms",   "frame MAD ms",
      "fastest ms", "visibility ms", "shading ms", "prepare ms", "culled by the z-pyramid",
      "identical"};
  if (perThread) heads.push_back("speed-up over one thread");
  if (comparison)
    for (const char* h : {"baseline ms", "ratio", "95% interval", "probed ratio",
                          "95% interval (probed)", "verdict"})
      heads.push_back(h);
  std::ostringstream t;
  t << "<div class=\"scroll\"><table class=\"cells\"><caption>Every cell: medians of " << run.repeat
    << " frames; click a column's header to sort by it</caption><thead><tr>";
  for (const std::string& h : heads)
    t << "<th scope=\"col\"><button type=\"button\">" << esc(h) << "</button></th>";
  t << "</tr></thead><tbody>";
  for (const BenchCell& c : run.cells) {
    const CellComparison* cmp = comparison ? comparison->find(c.key) : nullptr;
    const bool slower = cmp && cmp->verdict == Verdict::Slower;
    t << "<tr" << (slower ? " class=\"slower\"" : "") << "><td>" << esc(c.key.scene) << "</td>"
      << "<td data-value=\"" << c.key.width * c.key.height << "\">" << c.key.width << "×"
      << c.key.height << (c.key.msaa > 1 ? " MSAA " + std::to_string(c.key.msaa) : "") << " "
      << esc(c.key.shading) << "</td><td>" << esc(c.key.algorithm) << "</td>"
      << numberCell(c.frame.median, fixed(c.frame.median, 2))
      << numberCell(c.frame.mad, fixed(c.frame.mad, 2))
      << numberCell(c.frame.min, fixed(c.frame.min, 2))
      << numberCell(c.visibility.median, fixed(c.visibility.median, 2))
      << numberCell(c.shade.median, fixed(c.shade.median, 2))
      << numberCell(c.prepareMs, fixed(c.prepareMs, 1))
      << numberCell(double(c.stats["triangles_hzb_culled"].asUInt64()),
                    std::to_string(c.stats["triangles_hzb_culled"].asUInt64()))
      << "<td>" << (c.identical ? "yes" : "<strong>no</strong>") << "</td>";
    if (perThread) {
      const double up =
          c.oneThreadFrame && c.frame.median > 0 ? c.oneThreadFrame->median / c.frame.median : 0;
      t << numberCell(up, fixed(up, 2) + "×");
    }
    if (comparison) {
      if (cmp)
        t << numberCell(cmp->baselineMs, fixed(cmp->baselineMs, 2))
          << numberCell(cmp->ratio.ratio, fixed(cmp->ratio.ratio, 3))
          << numberCell(cmp->ratio.low, fixed(cmp->ratio.low, 3) + "–" + fixed(cmp->ratio.high, 3))
          << numberCell(cmp->probed.ratio, fixed(cmp->probed.ratio, 3))
          << numberCell(cmp->probed.low,
                        fixed(cmp->probed.low, 3) + "–" + fixed(cmp->probed.high, 3))
          << "<td>"
          << (slower ? "<strong>▲ slower" + std::string(cmp->failed ? ", beyond the limit" : "") +
                           "</strong>"
                     : std::string(verdictName(cmp->verdict)))
          << "</td>";
      else
        t << "<td data-value=\"0\">—</td><td data-value=\"0\">—</td><td data-value=\"0\">—</td>"
             "<td data-value=\"0\">—</td><td data-value=\"0\">—</td><td>not in the baseline</td>";
    }
    t << "</tr>";
  }
  t << "</tbody></table></div>";
  return t.str();
}

constexpr const char* kStyle = R"(
:root { color-scheme: light dark; --bg: #ffffff; --fg: #1a1a1a; --muted: #595959;
  --rule: #d0d0d0; --slower: #fde8e4; --grid: #e4e4e4; }
@media (prefers-color-scheme: dark) {
  :root { --bg: #121212; --fg: #ececec; --muted: #b0b0b0; --rule: #3a3a3a; --slower: #4a1f19;
    --grid: #2c2c2c; }
}
* { box-sizing: border-box; }
body { margin: 0 auto; max-width: 1120px; padding: 1rem; background: var(--bg); color: var(--fg);
  font: 16px/1.45 system-ui, sans-serif; }
h1 { font-size: 1.6rem; margin: 0.2rem 0 0.6rem; }
h2 { font-size: 1.25rem; margin: 2rem 0 0.6rem; border-top: 1px solid var(--rule);
  padding-top: 1rem; }
dl.run { display: grid; grid-template-columns: max-content 1fr; gap: 0.2rem 1rem; margin: 0; }
dl.run dt { color: var(--muted); }
dl.run dd { margin: 0; overflow-wrap: anywhere; }
code { font-family: ui-monospace, monospace; font-size: 0.9em; }
.scene { display: grid; grid-template-columns: minmax(0, 1fr) minmax(0, 2fr); gap: 1rem;
  align-items: start; }
@media (max-width: 760px) { .scene { grid-template-columns: minmax(0, 1fr); } }
figure { margin: 0; }
figure img { width: 100%; height: auto; display: block; border: 1px solid var(--rule); }
figcaption, caption { color: var(--muted); font-size: 0.9rem; text-align: left;
  padding: 0.3rem 0; }
svg.chart { width: 100%; min-width: 520px; height: auto; display: block; color: var(--fg); }
svg.chart text { font-size: 12px; fill: currentColor; }
svg.chart .grid { stroke: var(--grid); }
svg.chart .axis, svg.chart .median { stroke: currentColor; stroke-width: 1.5; }
svg.chart .box { fill-opacity: 0.3; }
svg.chart .baseline { fill: none; stroke: currentColor; stroke-width: 1.5; }
.scroll { overflow-x: auto; }
table { border-collapse: collapse; font-size: 0.92rem; font-variant-numeric: tabular-nums; }
th, td { padding: 0.3rem 0.55rem; border-bottom: 1px solid var(--rule); text-align: right;
  white-space: nowrap; }
th:first-child, td:first-child, td:nth-child(2), td:nth-child(3) { text-align: left; }
table.counters th { white-space: normal; }
table.counters th[scope=row] { text-align: left; font-weight: normal; }
th button { font: inherit; font-weight: 600; color: inherit; background: none; border: 0;
  padding: 0; cursor: pointer; text-align: inherit; }
th button:focus-visible { outline: 2px solid currentColor; }
th[aria-sort=ascending] button::after { content: " ▲"; }
th[aria-sort=descending] button::after { content: " ▼"; }
tr.slower td { background: var(--slower); }
footer { margin-top: 2rem; color: var(--muted); font-size: 0.9rem; }
)";

// Sorting: a click on a header orders the rows by that column, numbers by their data-value,
// words by their text; a second click reverses.
constexpr const char* kScript = R"(
document.querySelectorAll('table.cells th button').forEach((button, column) => {
  button.addEventListener('click', () => {
    const th = button.parentElement, table = th.closest('table'), body = table.tBodies[0];
    const ascending = th.getAttribute('aria-sort') !== 'ascending';
    table.querySelectorAll('th').forEach(h => h.removeAttribute('aria-sort'));
    th.setAttribute('aria-sort', ascending ? 'ascending' : 'descending');
    const key = row => {
      const cell = row.cells[column];
      return cell.dataset.value !== undefined ? Number(cell.dataset.value) : cell.textContent;
    };
    const rows = Array.from(body.rows).sort((a, b) => {
      const x = key(a), y = key(b);
      const order = typeof x === 'number' ? x - y : x.localeCompare(y);
      return ascending ? order : -order;
    });
    rows.forEach(row => body.appendChild(row));
  });
});
)";

}  // namespace

std::string benchHtml(const BenchRun& run, const BenchRun* baseline,
                      const BenchComparison* comparison) {
  std::ostringstream h;
  std::string command;
  for (const std::string& a : run.command) command += (command.empty() ? "" : " ") + a;
  h << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
       "<title>zrender bench, "
    << esc(run.date) << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n";
  h << "<header><h1>zrender bench</h1><dl class=\"run\">";
  auto row = [&](const std::string& term, const std::string& html) {
    h << "<dt>" << esc(term) << "</dt><dd>" << html << "</dd>";
  };
  row("machine", esc(run.cpu) + ", " + std::to_string(run.cores) + " cores");
  row("zrender",
      esc(run.version) +
          (run.commit.empty() ? ""
                              : ", commit <code>" + esc(run.commit.substr(0, 12)) + "</code>") +
          ", " + esc(run.compiler) + ", " + esc(run.buildType));
  row("date", esc(run.date));
  row("command", "<code>" + esc(command) + "</code>");
  row("frames", std::to_string(run.repeat) + " timed per cell after " + std::to_string(run.warmup) +
                    " untimed, on " + std::to_string(run.threads) +
                    (run.threads > 1 ? " threads (and on one, for the speed-up)" : " thread"));
  if (comparison) {
    const BenchComparison& c = *comparison;
    row("baseline",
        "<code>" + esc(c.baselineFile) + "</code>" +
            (c.baselineCommit.empty()
                 ? ""
                 : ", commit <code>" + esc(c.baselineCommit.substr(0, 12)) + "</code>") +
            ", " + esc(c.baselineDate) + ": " + std::to_string(c.count(Verdict::Slower)) +
            " slower, " + std::to_string(c.count(Verdict::Faster)) + " faster, " +
            std::to_string(c.count(Verdict::NoChange)) + " no change" +
            (c.maxSlowdownPct ? "; " + std::to_string(c.failures()) + " slower beyond " +
                                    fixed(*c.maxSlowdownPct, 0) + "%"
                              : std::string()));
  }
  h << "</dl></header>\n<main>\n";

  for (const Group& g : groupsOf(run)) {
    size_t identical = 0;
    std::string differing;
    for (const BenchCell* c : g.cells) {
      if (c->identical)
        ++identical;
      else
        differing += (differing.empty() ? "" : ", ") + c->key.algorithm;
    }
    h << "<section><h2>" << esc(groupTitle(g.key)) << "</h2><div class=\"scene\"><figure>";
    if (g.picture && !g.picture->imageUri.empty())
      h << "<img src=\"" << esc(g.picture->imageUri) << "\" alt=\"The frame of " << esc(g.key.scene)
        << " as every algorithm rendered it\">";
    else
      h << "<p>No picture in this results file.</p>";
    h << "<figcaption>"
      << (differing.empty()
              ? "The same frame for every algorithm: after the timed frames, each algorithm's "
                "color, depth and face-id buffers were compared with the z-buffer's, bit for "
                "bit, and all " +
                    std::to_string(identical) + " were identical."
              : "<strong>Not the same frame: the buffers of " + esc(differing) +
                    " differ from the z-buffer's.</strong>")
      << "</figcaption></figure><div><div class=\"scroll\">" << groupChart(g, baseline) << "</div>"
      << counters(g) << "</div></div></section>\n";
  }
  h << "<section><h2>All cells</h2>" << cellsTable(run, comparison) << "</section>\n";
  h << "</main>\n<footer>Made by zrender " << esc(run.version)
    << " from its results file: <code>zrender bench-report RESULTS.json --html FILE</code> "
       "makes this page again without rendering.</footer>\n";
  h << "<script>" << kScript << "</script>\n</body>\n</html>\n";
  return h.str();
}

}  // namespace zrender
