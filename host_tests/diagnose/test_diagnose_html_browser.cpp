// report.html of a real `sinu diagnose` (a simulated flight with a hidden
// lever arm) opened in headless Chromium: every plot drawn, the page's script
// run without an error, nothing referenced outside the file; and the page of a
// 30-minute flight stays small (min/max per pixel column).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstddef>
#include <filesystem>
#include <string>

#include "host_tests/support/run_process.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

constexpr const char* kChromium = "/usr/bin/chromium";

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

bool references_outside(const std::string& html) {
  return html.find("http://") != std::string::npos || html.find("https://") != std::string::npos ||
         html.find("src=") != std::string::npos || html.find("url(") != std::string::npos ||
         html.find("@import") != std::string::npos;
}

std::string diagnose_flight(const TempDir& dir, const std::string& duration) {
  const std::string ds = dir.file("flight"), out = dir.file("diag");
  const std::string effects = dir.write("effects.json", R"({"lever_arm": [0.9, -0.5, -0.6]})");
  EXPECT_EQ(run_sinu({"simulate", "flight", "--out", ds, "--seed", "9", "--duration", duration, "--effects", effects})
                .exit_code, 0);
  const auto r = run_sinu({"diagnose", "--in", ds, "--gps-latency", "0.045", "--rounds", "1", "--quiet", "--out", out});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(out + "/report.html"), std::string::npos) << r.out;
  return out + "/report.html";
}

// The DOM after the page's script has run (Chromium's --dump-dom), with no
// network and a profile of its own.
std::string dump_dom(const TempDir& dir, const std::string& page) {
  const auto r = run_process({"/usr/bin/timeout", "120", kChromium, "--headless", "--no-sandbox", "--disable-gpu",
                              "--disable-quic", "--no-first-run", "--disable-background-networking",
                              "--disable-component-update", "--disable-sync", "--user-data-dir=" + dir.file("profile"),
                              "--virtual-time-budget=5000", "--dump-dom", "file://" + page});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.out;
}

TEST(DiagnoseHtmlBrowser, EveryPlotIsDrawnAndTheScriptRunsWithoutErrors) {
  if (::access(kChromium, X_OK) != 0) GTEST_SKIP() << "Chromium missing (tools/setup.sh installs the package chromium)";
  TempDir dir;
  const std::string page = diagnose_flight(dir, "600");
  const std::string html = read_file(page);
  ASSERT_FALSE(html.empty());
  EXPECT_FALSE(references_outside(html));
  EXPECT_NE(html.find("Missing effect: lever_arm = ["), std::string::npos);
  const std::string dom = dump_dom(dir, page);
  ASSERT_NE(dom.find("</html>"), std::string::npos) << dom.substr(0, 2000);
  const std::size_t body_at = dom.find("<body");
  ASSERT_NE(body_at, std::string::npos);
  const std::string body = dom.substr(body_at, dom.find('>', body_at) - body_at + 1);
  EXPECT_NE(body.find("data-ok=\"1\""), std::string::npos) << body;
  EXPECT_EQ(body.find("data-errors"), std::string::npos) << body;
  // The simulated flight has GNSS position (3 components), velocity (2) and the magnetometer (3).
  const std::size_t plots = count(dom, "<figure class=\"tplot\"");
  EXPECT_GE(plots, 8u);
  EXPECT_NE(body.find("data-plots=\"" + std::to_string(plots) + "\""), std::string::npos) << body;
  // Each plot: the innovation line with many points, both sigma bands, time ticks the script wrote.
  const std::string inno = "<path class=\"inno\" d=\"M";
  std::size_t drawn = 0;
  for (std::size_t at = dom.find(inno); at != std::string::npos; at = dom.find(inno, at + 1)) {
    const std::size_t begin = at + inno.size();
    EXPECT_GT(count(dom.substr(begin, dom.find('"', begin) - begin), ","), 500u);
    ++drawn;
  }
  EXPECT_EQ(drawn, plots);
  EXPECT_EQ(count(dom, "<path class=\"s1\" d=\"M"), plots);
  EXPECT_EQ(count(dom, "<path class=\"s3\" d=\"M"), plots);
  EXPECT_GE(count(dom, "<text class=\"tick\" text-anchor=\"middle\""), 5 * plots);
  // The bar charts: NIS per phase and the candidates' evidence.
  EXPECT_GE(count(dom, "<svg class=\"plot bars\""), 1u);
  EXPECT_GE(count(dom, "<svg class=\"plot pairs\""), 1u);
}

// Min/max per pixel column: a 30-minute flight's page stays small.
TEST(DiagnoseHtmlFlight, AThirtyMinuteFlightsPageStaysUnderThreeMegabytes) {
  TempDir dir;
  const std::string page = diagnose_flight(dir, "1800");
  const auto bytes = std::filesystem::file_size(page);
  EXPECT_LT(bytes, 3u * 1024u * 1024u);
  EXPECT_GT(bytes, 100u * 1024u);
}

}  // namespace
}  // namespace sinu::test
