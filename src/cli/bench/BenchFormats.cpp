#include "zrender/cli/bench/BenchFormats.hpp"

#include <cstdio>
#include <sstream>

#include <json/json.h>

namespace zrender {

namespace {

std::string sizeText(const BenchKey& k) {
  return std::to_string(k.width) + "x" + std::to_string(k.height) +
         (k.msaa > 1 ? " MSAA" + std::to_string(k.msaa) : "");
}

std::string shortCommit(const std::string& commit) {
  return commit.empty() ? "unknown commit" : "commit " + commit.substr(0, 12);
}

std::string interval(const RatioInterval& r) {
  return fixed(r.low, 3) + "–" + fixed(r.high, 3);
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string keyList(const std::vector<BenchKey>& keys) {
  std::string s;
  for (const BenchKey& k : keys) s += (s.empty() ? "" : ", ") + k.text();
  return s;
}

}  // namespace

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string hexColor(uint32_t rgb) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%06x", rgb & 0xffffffu);
  return buf;
}

std::string xmlEscaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        // XML 1.0 has no other control characters than tab and the line breaks.
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\t' || c == '\n' || c == '\r') out += c;
    }
  }
  return out;
}

const BenchCell* zbufferCellOf(const BenchRun& run, const BenchCell& cell) {
  BenchKey key = cell.key;
  key.algorithm = "zbuffer";
  for (const BenchCell& c : run.cells)
    if (c.key == key) return &c;
  return nullptr;
}

std::string benchMarkdown(const BenchRun& run, const BenchComparison* comparison) {
  std::ostringstream md;
  const bool perThread = run.threads > 1;
  md << "zrender bench: median of " << run.repeat << " frames, "
     << (perThread ? std::to_string(run.threads) + " threads" : std::string("one thread")) << ", "
     << run.cpu << ", " << run.cores << " cores, " << run.date.substr(0, 10) << "\n\n";
  md << "| scene | size | algorithm | visibility ms | raster ms | frame ms | frame MAD ms | "
        "raster speed-up | frame speed-up | "
     << (perThread ? "one thread: frame ms | speed-up over one thread | " : "")
     << "prepare ms | triangles culled by HZB | octree nodes culled | identical |\n";
  md << "|---|---|---|---:|---:|---:|---:|---:|---:|" << (perThread ? "---:|---:|" : "")
     << "---:|---:|---:|---|\n";
  for (const BenchCell& c : run.cells) {
    const BenchCell* z = zbufferCellOf(run, c);
    const double rasterUp = z && c.raster.median > 0 ? z->raster.median / c.raster.median : 0;
    const double frameUp = z && c.frame.median > 0 ? z->frame.median / c.frame.median : 0;
    md << "| " << c.key.scene << " | " << sizeText(c.key)
       << (c.key.shading != "normal" ? " " + c.key.shading : "") << " | " << c.key.algorithm
       << " | " << fixed(c.visibility.median, 2) << " | " << fixed(c.raster.median, 2) << " | "
       << fixed(c.frame.median, 2) << " | " << fixed(c.frame.mad, 2) << " | " << fixed(rasterUp, 2)
       << "x | " << fixed(frameUp, 2) << "x | ";
    if (perThread) {
      const double one = c.oneThreadFrame ? c.oneThreadFrame->median : 0;
      md << fixed(one, 2) << " | " << fixed(c.frame.median > 0 ? one / c.frame.median : 0, 2)
         << "x | ";
    }
    md << fixed(c.prepareMs, 1) << " | " << c.stats["triangles_hzb_culled"].asUInt64() << " | "
       << c.stats["octree_nodes_culled"].asUInt64() << "/"
       << c.stats["octree_nodes_visited"].asUInt64() << " | " << (c.identical ? "yes" : "**NO**")
       << " |\n";
  }
  if (!comparison) return md.str();

  const BenchComparison& cmp = *comparison;
  md << "\nCompared with " << cmp.baselineFile << " (" << shortCommit(cmp.baselineCommit) << ", "
     << cmp.baselineDate.substr(0, 10) << "): " << cmp.count(Verdict::Slower) << " slower, "
     << cmp.count(Verdict::Faster) << " faster, " << cmp.count(Verdict::NoChange)
     << " no change (ratio of median frame times, then of frames divided by the machine-speed "
        "probe; 95% intervals; a change must show in both)";
  if (cmp.maxSlowdownPct)
    md << "; " << cmp.failures() << " slower by more than " << fixed(*cmp.maxSlowdownPct, 0) << "%";
  md << ".\n\n";
  md << "| scene | size | algorithm | baseline ms | frame ms | ratio | 95% interval | "
        "probed ratio | 95% interval | verdict |\n";
  md << "|---|---|---|---:|---:|---:|---|---:|---|---|\n";
  for (const CellComparison& c : cmp.cells) {
    const std::string verdict = verdictName(c.verdict);
    md << "| " << c.key.scene << " | " << sizeText(c.key)
       << (c.key.shading != "normal" ? " " + c.key.shading : "") << " | " << c.key.algorithm
       << " | " << fixed(c.baselineMs, 2) << " | " << fixed(c.currentMs, 2) << " | "
       << fixed(c.ratio.ratio, 3) << " | " << interval(c.ratio) << " | " << fixed(c.probed.ratio, 3)
       << " | " << interval(c.probed) << " | "
       << (c.failed ? "**" + verdict + "** (beyond the limit)" : verdict) << " |\n";
  }
  if (!cmp.onlyInCurrent.empty())
    md << "\nOnly in this run: " << keyList(cmp.onlyInCurrent) << ".\n";
  if (!cmp.onlyInBaseline.empty())
    md << "\nOnly in the baseline: " << keyList(cmp.onlyInBaseline) << ".\n";
  return md.str();
}

std::string benchCsv(const BenchRun& run, const BenchComparison* comparison) {
  std::ostringstream csv;
  csv << "scene,algorithm,width,height,msaa,shading,faces,threads,frames,frame_median_ms,"
         "frame_mad_ms,frame_min_ms,transform_median_ms,visibility_median_ms,shade_median_ms,"
         "raster_median_ms,prepare_ms,identical,baseline_median_ms,ratio,ratio_low,ratio_high,"
         "probed_ratio,probed_low,probed_high,verdict\r\n";
  for (const BenchCell& c : run.cells) {
    csv << csvField(c.key.scene) << "," << csvField(c.key.algorithm) << "," << c.key.width << ","
        << c.key.height << "," << c.key.msaa << "," << csvField(c.key.shading) << "," << c.faces
        << "," << run.threads << "," << c.frame.samples.size() << "," << fixed(c.frame.median, 4)
        << "," << fixed(c.frame.mad, 4) << "," << fixed(c.frame.min, 4) << ","
        << fixed(c.transform.median, 4) << "," << fixed(c.visibility.median, 4) << ","
        << fixed(c.shade.median, 4) << "," << fixed(c.raster.median, 4) << ","
        << fixed(c.prepareMs, 4) << "," << (c.identical ? "true" : "false") << ",";
    const CellComparison* cmp = comparison ? comparison->find(c.key) : nullptr;
    if (cmp)
      csv << fixed(cmp->baselineMs, 4) << "," << fixed(cmp->ratio.ratio, 4) << ","
          << fixed(cmp->ratio.low, 4) << "," << fixed(cmp->ratio.high, 4) << ","
          << fixed(cmp->probed.ratio, 4) << "," << fixed(cmp->probed.low, 4) << ","
          << fixed(cmp->probed.high, 4) << "," << csvField(verdictName(cmp->verdict));
    else
      csv << ",,,,,,,";
    csv << "\r\n";
  }
  return csv.str();
}

std::string benchJunit(const BenchRun& run, const BenchComparison* comparison) {
  size_t failures = 0;
  double total = 0;
  std::ostringstream cases;
  for (const BenchCell& c : run.cells) {
    const double seconds = c.frame.median / 1000;
    total += seconds;
    cases << "    <testcase classname=\"zrender.bench." << xmlEscaped(c.key.scene) << "\" name=\""
          << xmlEscaped(c.key.text()) << "\" time=\"" << fixed(seconds, 6) << "\">\n";
    const CellComparison* cmp = comparison ? comparison->find(c.key) : nullptr;
    if (!c.identical) {
      ++failures;
      cases << "      <failure type=\"disagreement\" message=\"" << xmlEscaped(c.key.algorithm)
            << "'s buffers differ from zbuffer's\"/>\n";
    } else if (cmp && cmp->failed) {
      ++failures;
      cases << "      <failure type=\"slowdown\" message=\"median frame "
            << fixed(cmp->currentMs, 3) << " ms against " << fixed(cmp->baselineMs, 3)
            << " ms: ratio " << fixed(cmp->ratio.ratio, 3) << ", 95% interval "
            << fixed(cmp->ratio.low, 3) << " to " << fixed(cmp->ratio.high, 3) << "; probed ratio "
            << fixed(cmp->probed.ratio, 3) << ", 95% interval " << fixed(cmp->probed.low, 3)
            << " to " << fixed(cmp->probed.high, 3) << ", beyond --max-slowdown "
            << fixed(*comparison->maxSlowdownPct, 1) << "%\"/>\n";
    }
    cases << "      <system-out>median " << fixed(c.frame.median, 3) << " ms, MAD "
          << fixed(c.frame.mad, 3) << " ms, min " << fixed(c.frame.min, 3) << " ms over "
          << c.frame.samples.size() << " frames"
          << (cmp ? "; against the baseline: " + std::string(verdictName(cmp->verdict)) +
                        ", ratio " + fixed(cmp->ratio.ratio, 3) + " (95% interval " +
                        fixed(cmp->ratio.low, 3) + " to " + fixed(cmp->ratio.high, 3) + ")"
                  : std::string())
          << "</system-out>\n";
    cases << "    </testcase>\n";
  }
  std::ostringstream xml;
  const std::string counts = "tests=\"" + std::to_string(run.cells.size()) + "\" failures=\"" +
                             std::to_string(failures) + "\" errors=\"0\" time=\"" +
                             fixed(total, 6) + "\"";
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml << "<testsuites name=\"zrender bench\" " << counts << ">\n";
  xml << "  <testsuite name=\"zrender bench\" " << counts << " timestamp=\"" << xmlEscaped(run.date)
      << "\">\n";
  xml << "    <properties>\n";
  auto property = [&](const char* name, const std::string& value) {
    xml << "      <property name=\"" << name << "\" value=\"" << xmlEscaped(value) << "\"/>\n";
  };
  property("zrender", run.version);
  property("commit", run.commit);
  property("cpu", run.cpu);
  property("threads", std::to_string(run.threads));
  if (comparison) property("baseline", comparison->baselineFile);
  xml << "    </properties>\n" << cases.str() << "  </testsuite>\n</testsuites>\n";
  return xml.str();
}

std::string benchActionJson(const BenchRun& run) {
  Json::Value all(Json::arrayValue);
  for (const BenchCell& c : run.cells) {
    Json::Value e(Json::objectValue);
    e["name"] = c.key.text();
    e["unit"] = "ms";
    e["value"] = c.frame.median;
    e["range"] = "± " + fixed(c.frame.mad, 3);
    e["extra"] = "median of " + std::to_string(c.frame.samples.size()) + " frames, min " +
                 fixed(c.frame.min, 3) + " ms, " + std::to_string(run.threads) + " thread(s), " +
                 run.cpu;
    all.append(e);
  }
  Json::StreamWriterBuilder builder;
  builder["indentation"] = "  ";
  builder["precision"] = 4;
  builder["precisionType"] = "decimal";
  builder["emitUTF8"] = true;
  return Json::writeString(builder, all) + "\n";
}

}  // namespace zrender
