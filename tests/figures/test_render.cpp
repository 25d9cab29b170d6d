// Unit tests of molchaos::figures: every figure renders from small synthetic data into PNG, PDF
// and its gnuplot script; bad data and a missing gnuplot give errors that name the culprit.
// Set MOLCHAOS_FIGURES_TEST_OUTPUT to a directory to keep the rendered figures for a look.
#define BOOST_TEST_MODULE figures_render
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>
#include <stdexcept>
#include <string>
#include <thread>

#include "molchaos/figures/render.hpp"

namespace fs = std::filesystem;
namespace fig = molchaos::figures;
namespace val = molchaos::validation;

namespace {

// A fresh directory, removed afterwards unless MOLCHAOS_FIGURES_TEST_OUTPUT asks to keep it.
struct OutputDirectory {
  fs::path path;
  bool keep = false;
  explicit OutputDirectory(const std::string& name) {
    if (const char* keep_in = std::getenv("MOLCHAOS_FIGURES_TEST_OUTPUT")) {
      path = fs::path(keep_in) / name;
      keep = true;
    } else {
      path = fs::temp_directory_path() /
             ("molchaos_figures_" + name + "_" + std::to_string(std::random_device{}()));
    }
    fs::remove_all(path);
  }
  ~OutputDirectory() {
    if (!keep) fs::remove_all(path);
  }
  fig::RenderOptions options() const { return {path.string(), true, true}; }
};

std::string first_bytes(const fs::path& path, std::size_t count) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(count, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(count));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

// Every file reported exists and is non-empty, images carry their magic bytes, and the
// directory holds nothing else (no temporary left behind).
void check_rendered(const fig::RenderedFigure& rendered, const fs::path& directory,
                    const std::string& basename) {
  BOOST_TEST(rendered.files.size() == 3u);
  for (const std::string ext : {".png", ".pdf", ".gp"}) {
    const fs::path file = directory / (basename + ext);
    BOOST_TEST_INFO(file.string());
    BOOST_TEST(fs::exists(file));
    BOOST_TEST(fs::file_size(file) > 0u);
    const bool reported = std::find(rendered.files.begin(), rendered.files.end(), file.string()) !=
                          rendered.files.end();
    BOOST_TEST(reported);
  }
  BOOST_TEST(first_bytes(directory / (basename + ".png"), 8) == std::string("\x89PNG\r\n\x1a\n"));
  BOOST_TEST(first_bytes(directory / (basename + ".pdf"), 4) == std::string("%PDF"));
  for (const auto& entry : fs::directory_iterator(directory)) {
    const auto name = entry.path().filename().string();
    BOOST_TEST_INFO(name);
    BOOST_TEST(name.rfind(basename + ".", 0) == 0u);
  }
}

// Haff's law, Eq. (2), in units T0 = 1.
double haff(double t, double tau0) { return 1.0 / ((1.0 + t / tau0) * (1.0 + t / tau0)); }

val::Fig3Data synthetic_fig3() {
  constexpr double tau_theory = 20.0, tau_fitted = 20.6, onset = 403.0;  // ln 403 ≈ 6
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  val::Fig3Data data;
  data.clustering_onset = onset;
  val::TemperatureCurve original{"original gas (no shuffle)", {}, {}, {}, false, "none"};
  val::TemperatureCurve randomized{"randomized gas (flux)", {}, {}, {}, false, "flux"};
  val::TemperatureCurve theory{"Haff's law, τ_0 from kinetic theory", {}, {}, {}, true, ""};
  val::TemperatureCurve fitted{"Haff's law, fitted τ_0", {}, {}, {}, true, ""};
  for (int i = 0; i <= 300; ++i) {
    const double t = i == 0 ? 0.0 : std::exp(-2.0 + 10.5 * i / 300.0);
    // After the onset the clustered gas cools more slowly.
    const double slow = t > onset ? std::pow(t / onset, 0.6) : 1.0;
    const double T_original = haff(t, tau_fitted) * slow;
    const double T_random = haff(t, tau_theory);
    original.t.push_back(t);
    original.T.push_back(T_original * (1.0 + 0.002 * noise(rng)));
    original.T_error.push_back(0.003 * T_original);
    randomized.t.push_back(t);
    randomized.T.push_back(T_random * (1.0 + 0.002 * noise(rng)));
    randomized.T_error.push_back(0.003 * T_random);
    theory.t.push_back(t);
    theory.T.push_back(haff(t, tau_theory));
    fitted.t.push_back(t);
    fitted.T.push_back(haff(t, tau_fitted));
  }
  data.curves = {original, randomized, theory, fitted};
  return data;
}

val::Fig4Data synthetic_fig4() {
  val::Fig4Data data;
  for (const double density : {0.05, 0.1}) {
    val::Fig4Panel panel;
    panel.density = density;
    const double a_rand = 1.0 / (density * 12.0);
    val::ASeries original{"original gas", "none", {}, std::nullopt};
    val::ASeries randomized{"randomized gas (flux)", "flux", {}, std::nullopt};
    for (int i = 0; i < 10; ++i) {
      const double eps = 0.80 + 0.02 * i;
      original.points.push_back({eps, {a_rand * (1.0 + 0.35 * (1.0 - eps)), 0.004 * a_rand}, 8});
      randomized.points.push_back(
          {eps, {a_rand * (1.0 + 0.004 * std::sin(9.0 * eps)), 0.004 * a_rand}, 8});
      panel.theory_restitution.push_back(eps);
      panel.theory_A.push_back(a_rand * (1.0 - 0.002 * (1.0 - eps)));
    }
    original.fit = val::LinearFit{a_rand * 1.35, 0.01, -0.35 * a_rand, 0.01, 1.1};
    randomized.fit = val::LinearFit{a_rand, 0.01, 0.0, 0.01, 0.9};
    panel.series = {original, randomized};
    data.panels.push_back(panel);
  }
  return data;
}

val::BData synthetic_b() {
  val::BData data;
  for (const double density : {0.05, 0.1}) {
    val::BPanel panel{density, {}};
    for (int s = 0; s < 3; ++s) {
      val::BSeries series;
      series.label = s == 0 ? "from A, paper's 63/40 and ω_0"
                            : (s == 1 ? "from A, suite's coefficient" : "contact statistics");
      for (int i = 0; i < 10; ++i) {
        const double eps = 0.80 + 0.02 * i;
        series.restitution.push_back(eps);
        series.b.push_back({0.2 * (1.0 - eps) * (1.0 + 0.1 * s), 0.005});
      }
      panel.series.push_back(series);
    }
    data.panels.push_back(panel);
  }
  return data;
}

val::A2Data synthetic_a2() {
  val::A2Data data;
  for (const double density : {0.05, 0.1}) {
    val::A2Panel panel;
    panel.density = density;
    for (const char* mode : {"none", "paper", "flux", "dsmc"}) {
      val::A2Series series{std::string("gas ") + mode, mode, {}, {}, {}};
      for (int i = 0; i < 10; ++i) {
        const double eps = 0.80 + 0.02 * i;
        series.restitution.push_back(eps);
        series.a2.push_back({-0.1 * (1.0 - eps), 0.003});
      }
      panel.series.push_back(series);
    }
    for (int i = 0; i <= 40; ++i) {
      const double eps = 0.80 + 0.005 * i;
      panel.theory_restitution.push_back(eps);
      panel.first_sonine.push_back({-0.09 * (1.0 - eps), 0.0});
      panel.improved.push_back({-0.11 * (1.0 - eps), 1e-13});
    }
    data.panels.push_back(panel);
  }
  return data;
}

val::SnapshotData synthetic_snapshot() {
  // Particles gathered into a band along a shear flow, with two counter-rotating vortices.
  val::SnapshotData data;
  data.box = 100.0;
  data.time = 800.0;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(0.0, 100.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  constexpr double k_pi = 3.14159265358979323846;
  for (int i = 0; i < 2000; ++i) {
    const double x = uniform(rng);
    double y = i % 3 == 0 ? uniform(rng)
                          : 50.0 + 6.0 * normal(rng) + 15.0 * std::sin(2 * k_pi * x / 100.0);
    y = y - 100.0 * std::floor(y / 100.0);
    data.x.push_back(x);
    data.y.push_back(y);
    data.speed.push_back(std::abs(1.0 + 0.5 * normal(rng)));
  }
  for (int i = 0; i < 12; ++i) {
    for (int j = 0; j < 12; ++j) {
      const double x = (i + 0.5) * 100.0 / 12, y = (j + 0.5) * 100.0 / 12;
      data.grid_x.push_back(x);
      data.grid_y.push_back(y);
      data.grid_vx.push_back(std::sin(2 * k_pi * y / 100.0) * std::cos(k_pi * x / 100.0 * 2));
      data.grid_vy.push_back(-std::cos(2 * k_pi * y / 100.0) * std::sin(k_pi * x / 100.0 * 2));
    }
  }
  return data;
}

val::WorkPrecisionData synthetic_work_precision() {
  val::WorkPrecisionData data;
  data.title = "quadrature of μ_2 and a_2";
  for (int k = 3; k <= 12; ++k) {
    const double tolerance = std::pow(10.0, -k);
    data.points.push_back({tolerance, 1e-5 * k * k, 0.1 * tolerance, 0.8 * tolerance});
  }
  data.points.back().max_error_reached = 0.0;  // exact to the last bit: left off the log axis
  return data;
}

val::SimulationWorkPrecisionData synthetic_simulation_cost() {
  val::SimulationWorkPrecisionData data;
  data.title = "flux gas";
  for (int k = 0; k < 3; ++k)
    data.points.push_back(
        {1000 * (k + 1), 40, 0.1 * (k + 1), 0.011 / std::sqrt(k + 1.0), 1e-4, 2e-4});
  return data;
}

std::vector<val::ImpactParameterRow> synthetic_impact_parameter() {
  // Two panels, two restitutions, both gases: the original gas short of grazing collisions.
  std::vector<val::ImpactParameterRow> rows;
  for (const auto& [d, n] : {std::pair{2, 0.1}, std::pair{3, 0.1}})
    for (double eps : {0.8, 0.9})
      for (const std::string mode : {"none", "flux"})
        for (int b = 0; b < 10; ++b) {
          val::ImpactParameterRow r;
          r.dimension = d;
          r.density = n;
          r.restitution = eps;
          r.mode = mode;
          r.runs = 8;
          r.s_lo = 0.1 * b;
          r.s_hi = 0.1 * (b + 1);
          const double tilt = mode == "none" ? 0.02 * (1.0 - eps) * (4.5 - b) : 0.0;
          r.fraction = {0.1 * (1.0 + tilt), 4e-4};
          rows.push_back(r);
        }
  return rows;
}

template <class Function>
void check_invalid_argument(Function&& function, const std::string& field) {
  try {
    function();
    BOOST_FAIL("no std::invalid_argument, expected one naming " + field);
  } catch (const std::invalid_argument& e) {
    BOOST_TEST_INFO(e.what());
    BOOST_TEST(std::string(e.what()).find(field) != std::string::npos);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(fig3_renders_png_pdf_and_script) {
  const OutputDirectory out("fig3");
  const auto rendered = fig::render_fig3(synthetic_fig3(), out.options());
  check_rendered(rendered, out.path, "fig3_temperature");
}

BOOST_AUTO_TEST_CASE(fig4_renders_png_pdf_and_script) {
  const OutputDirectory out("fig4");
  check_rendered(fig::render_fig4(synthetic_fig4(), out.options()), out.path, "fig4_A_of_eps");
}

BOOST_AUTO_TEST_CASE(b_renders_png_pdf_and_script) {
  const OutputDirectory out("b");
  check_rendered(fig::render_b(synthetic_b(), out.options()), out.path, "fig_b_of_eps");
}

// One run per point gives no b at contact (it needs the standard error of the mean dyad): the
// empty series is left out and the rest is drawn.
BOOST_AUTO_TEST_CASE(b_renders_without_an_empty_series) {
  const OutputDirectory out("b_empty_series");
  auto b = synthetic_b();
  b.panels[0].series[2] = {b.panels[0].series[2].label, {}, {}};
  check_rendered(fig::render_b(b, out.options()), out.path, "fig_b_of_eps");
}

BOOST_AUTO_TEST_CASE(a2_renders_png_pdf_and_script) {
  const OutputDirectory out("a2");
  check_rendered(fig::render_a2(synthetic_a2(), out.options()), out.path, "fig_a2_of_eps");
  // The script carries every point and both theory lines as data blocks, so it redraws alone.
  std::ifstream script(out.path / "fig_a2_of_eps.gp");
  const std::string text((std::istreambuf_iterator<char>(script)), {});
  for (const std::string block : {"$p0_s3", "$p1_s0", "$p0_theory", "$p1_theory"}) {
    BOOST_TEST_INFO(block);
    BOOST_TEST(text.find(block) != std::string::npos);
  }
}

BOOST_AUTO_TEST_CASE(snapshot_renders_png_pdf_and_script) {
  const OutputDirectory out("snapshot");
  check_rendered(fig::render_snapshot(synthetic_snapshot(), out.options()), out.path,
                 "fig_snapshot");
}

BOOST_AUTO_TEST_CASE(work_precision_renders_png_pdf_and_script) {
  const OutputDirectory out("work_precision");
  check_rendered(fig::render_work_precision(synthetic_work_precision(), out.options(), "fig_wp"),
                 out.path, "fig_wp");
}

BOOST_AUTO_TEST_CASE(simulation_cost_renders_png_pdf_and_script) {
  const OutputDirectory out("simulation_cost");
  check_rendered(fig::render_simulation_cost(synthetic_simulation_cost(), out.options()), out.path,
                 "work_precision_simulation");
}

BOOST_AUTO_TEST_CASE(impact_parameter_renders_png_pdf_and_script) {
  const OutputDirectory out("impact_parameter");
  check_rendered(fig::render_impact_parameter(synthetic_impact_parameter(), out.options()),
                 out.path, "fig_impact_parameter");
  check_invalid_argument([&] { fig::render_impact_parameter({}, out.options()); }, "rows");
}

BOOST_AUTO_TEST_CASE(linear_hydrodynamics_renders_png_pdf_and_script) {
  const OutputDirectory out("linear_hydrodynamics");
  val::StructureFactorCurve curve;
  curve.dimension = 3;
  curve.wavenumber = 0.26;
  curve.box = 24;
  curve.tau = {1, 2, 3};
  curve.measured = {1.2, 1.5, 1.9};
  curve.error = {0.1, 0.1, 0.2};
  curve.predicted = {1.2, 1.6, 2.0};
  check_rendered(fig::render_linear_hydrodynamics({curve}, "d = 3", "fig_sf3", out.options()),
                 out.path, "fig_sf3");
  check_invalid_argument(
      [&] { fig::render_linear_hydrodynamics({}, "d = 3", "fig_sf3", out.options()); }, "curves");
}

// The same data give the same bytes: cairo stamps a PDF with the second of its creation, which
// the renderer blanks (two renderings over a second apart, compared whole).
BOOST_AUTO_TEST_CASE(the_same_data_give_the_same_pdf) {
  const OutputDirectory first("same_pdf_1"), second("same_pdf_2");
  fig::render_fig4(synthetic_fig4(), first.options());
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  fig::render_fig4(synthetic_fig4(), second.options());
  auto bytes = [](const fs::path& path) { return first_bytes(path, fs::file_size(path)); };
  const std::string a = bytes(first.path / "fig4_A_of_eps.pdf");
  BOOST_TEST(a.find("/CreationDate") == std::string::npos);
  BOOST_TEST(a.find("%%EOF") != std::string::npos);  // whole
  BOOST_TEST((a == bytes(second.path / "fig4_A_of_eps.pdf")));
}

BOOST_AUTO_TEST_CASE(png_only_writes_no_pdf) {
  const OutputDirectory out("png_only");
  auto options = out.options();
  options.pdf = false;
  const auto rendered = fig::render_fig4(synthetic_fig4(), options);
  BOOST_TEST(rendered.files.size() == 2u);
  BOOST_TEST(fs::exists(out.path / "fig4_A_of_eps.png"));
  BOOST_TEST(!fs::exists(out.path / "fig4_A_of_eps.pdf"));
}

BOOST_AUTO_TEST_CASE(bad_data_throws_invalid_argument_naming_the_field) {
  const OutputDirectory out("bad");
  auto fig4 = synthetic_fig4();
  fig4.panels[1].series.clear();
  check_invalid_argument([&] { fig::render_fig4(fig4, out.options()); },
                         "Fig4Data.panels[1].series");
  fig4 = synthetic_fig4();
  fig4.panels[0].series[1].points.clear();
  check_invalid_argument([&] { fig::render_fig4(fig4, out.options()); },
                         "Fig4Data.panels[0].series[1].points");
  fig4 = synthetic_fig4();
  fig4.panels[0].theory_A.pop_back();
  check_invalid_argument([&] { fig::render_fig4(fig4, out.options()); },
                         "Fig4Data.panels[0].theory_A");
  check_invalid_argument([&] { fig::render_fig4(val::Fig4Data{}, out.options()); },
                         "Fig4Data.panels");

  auto fig3 = synthetic_fig3();
  fig3.curves[2].T.pop_back();
  check_invalid_argument([&] { fig::render_fig3(fig3, out.options()); }, "Fig3Data.curves[2].T");
  fig3 = synthetic_fig3();
  fig3.curves[0].T_error.resize(3);
  check_invalid_argument([&] { fig::render_fig3(fig3, out.options()); },
                         "Fig3Data.curves[0].T_error");

  auto b = synthetic_b();
  b.panels[0].series[2].b.pop_back();
  check_invalid_argument([&] { fig::render_b(b, out.options()); }, "BData.panels[0].series[2].b");
  b = synthetic_b();
  for (auto& series : b.panels[0].series) series = {series.label, {}, {}};
  check_invalid_argument([&] { fig::render_b(b, out.options()); },
                         "BData.panels[0].series[*].restitution");

  auto a2 = synthetic_a2();
  a2.panels[1].series[3].a2.pop_back();
  check_invalid_argument([&] { fig::render_a2(a2, out.options()); },
                         "A2Data.panels[1].series[3].a2");
  a2 = synthetic_a2();
  a2.panels[0].improved.pop_back();
  check_invalid_argument([&] { fig::render_a2(a2, out.options()); }, "A2Data.panels[0].improved");
  a2 = synthetic_a2();
  a2.panels[0].series.clear();
  check_invalid_argument([&] { fig::render_a2(a2, out.options()); }, "A2Data.panels[0].series");
  check_invalid_argument([&] { fig::render_a2(val::A2Data{}, out.options()); }, "A2Data.panels");

  auto snapshot = synthetic_snapshot();
  snapshot.speed.pop_back();
  check_invalid_argument([&] { fig::render_snapshot(snapshot, out.options()); },
                         "SnapshotData.speed");
  snapshot = synthetic_snapshot();
  snapshot.grid_vy.pop_back();
  check_invalid_argument([&] { fig::render_snapshot(snapshot, out.options()); },
                         "SnapshotData.grid_vy");

  auto wp = synthetic_work_precision();
  wp.points[0].seconds = 0.0;
  check_invalid_argument([&] { fig::render_work_precision(wp, out.options(), "wp"); },
                         "WorkPrecisionData.points[0].seconds");

  auto cost = synthetic_simulation_cost();
  cost.points[1].cpu_seconds_per_run = 0.0;
  check_invalid_argument([&] { fig::render_simulation_cost(cost, out.options()); },
                         "SimulationWorkPrecisionData.points[1]");
  check_invalid_argument(
      [&] { fig::render_simulation_cost(val::SimulationWorkPrecisionData{}, out.options()); },
      "SimulationWorkPrecisionData.points");

  // Nothing is written for data that cannot be drawn.
  BOOST_TEST((!fs::exists(out.path) || fs::is_empty(out.path)));
}

BOOST_AUTO_TEST_CASE(missing_gnuplot_throws_runtime_error_naming_the_file) {
  const OutputDirectory out("missing_gnuplot");
  auto options = out.options();
  options.gnuplot_executable = "molchaos-no-such-gnuplot";
  try {
    fig::render_fig4(synthetic_fig4(), options);
    BOOST_FAIL("no std::runtime_error");
  } catch (const std::runtime_error& e) {
    BOOST_TEST_INFO(e.what());
    BOOST_TEST(std::string(e.what()).find("fig4_A_of_eps.png") != std::string::npos);
    BOOST_TEST(std::string(e.what()).find("molchaos-no-such-gnuplot") != std::string::npos);
  }
  BOOST_TEST(fs::is_empty(out.path));  // no temporary left behind
}

BOOST_AUTO_TEST_CASE(gnuplot_failure_throws_runtime_error_with_its_message) {
  // `false` runs and exits with status 1, as gnuplot does on a script error.
  const OutputDirectory out("failing_gnuplot");
  auto options = out.options();
  options.gnuplot_executable = "false";
  try {
    fig::render_b(synthetic_b(), options);
    BOOST_FAIL("no std::runtime_error");
  } catch (const std::runtime_error& e) {
    BOOST_TEST_INFO(e.what());
    BOOST_TEST(std::string(e.what()).find("fig_b_of_eps.png") != std::string::npos);
    BOOST_TEST(std::string(e.what()).find("exit status 1") != std::string::npos);
  }
  BOOST_TEST(fs::is_empty(out.path));
}

// While gnuplot runs, the outputs and the script exist only under the atomic writer's temporary
// names (".<file>.molchaos-tmp.<host>.<pid>.<16 hex digits>"), the one pattern that
// sim::remove_stale_temporaries clears after a killed run; on failure none is left.
BOOST_AUTO_TEST_CASE(temporaries_carry_the_atomic_writers_names) {
  const OutputDirectory out("temporary_names");
  const fs::path tool = fs::temp_directory_path() /
                        ("molchaos_fake_gnuplot_" + std::to_string(std::random_device{}()));
  fs::create_directories(tool);
  const fs::path record = tool / "names.txt";
  {
    std::ofstream script(tool / "gnuplot");
    // Arguments as render() passes them: -e <assignments> <script>.
    script << "#!/bin/sh\nls -A \"$(dirname \"$3\")\" > '" << record.string() << "'\nexit 1\n";
  }
  fs::permissions(tool / "gnuplot", fs::perms::owner_all);
  auto options = out.options();
  options.gnuplot_executable = (tool / "gnuplot").string();
  BOOST_CHECK_THROW(fig::render_b(synthetic_b(), options), std::runtime_error);
  std::ifstream in(record);
  const std::regex pattern(
      R"(\.fig_b_of_eps\.(png|pdf|gp)\.molchaos-tmp\.[^./]+\.[0-9]+\.[0-9a-f]{16})");
  int names = 0;
  for (std::string name; std::getline(in, name); ++names) {
    BOOST_TEST_INFO(name);
    BOOST_TEST(std::regex_match(name, pattern));
  }
  BOOST_TEST(names == 1);  // the script (gnuplot writes the images)
  BOOST_TEST(fs::is_empty(out.path));
  fs::remove_all(tool);
}
