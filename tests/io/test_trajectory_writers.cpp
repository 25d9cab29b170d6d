// The trajectory writers write under a temporary name and rename at the end: a file that cannot
// be put in place (here: the target is a folder) is an error, and the temporary is gone.
#define BOOST_TEST_MODULE trajectory_writers
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "molchaos/io/h5md_writer.hpp"
#include "molchaos/io/xyz_writer.hpp"
#include "molchaos/sim/result.hpp"

namespace fs = std::filesystem;
using molchaos::sim::RunResult;

namespace {

// Two disks, one frame.
RunResult two_disks() {
  RunResult r;
  r.parameters.dimension = 2;
  r.parameters.particles = 2;
  r.parameters.snapshot_times = {1.0};
  molchaos::sim::Snapshot s;
  s.t = 1.0;
  s.box = 10.0;
  s.collisions = 3;
  s.positions = {1.0, 2.0, 5.0, 6.0};
  s.velocities = {0.5, -0.5, -0.5, 0.5};
  r.snapshots.push_back(s);
  return r;
}

// A fresh, empty folder for one case.
fs::path fresh_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("molchaos_test_writers_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

using Writer = std::function<void(const RunResult&, const std::string&)>;

void check_writer(const std::string& name, const Writer& write) {
  const fs::path dir = fresh_folder(name);
  // A target that is a folder with a file in it: the rename onto it fails.
  const fs::path blocked = dir / "run.out";
  fs::create_directories(blocked);
  std::ofstream(blocked / "keep").put('x');
  BOOST_CHECK_THROW(write(two_disks(), blocked.string()), std::runtime_error);
  BOOST_CHECK(entries(dir) == std::vector<std::string>{"run.out"});  // no temporary left
  BOOST_CHECK(fs::is_directory(blocked) && fs::exists(blocked / "keep"));
  // The same data to a free name: the file alone.
  write(two_disks(), (dir / "ok.out").string());
  BOOST_CHECK(fs::file_size(dir / "ok.out") > 0);
  BOOST_CHECK_EQUAL(entries(dir).size(), 2u);
  fs::remove_all(dir);
}

}  // namespace

BOOST_AUTO_TEST_CASE(h5md_failed_rename_leaves_no_temporary) {
  check_writer("h5md", [](const RunResult& r, const std::string& path) {
    molchaos::io::write_h5md_file(r, path);
  });
}

BOOST_AUTO_TEST_CASE(xyz_failed_rename_leaves_no_temporary) {
  check_writer("xyz", [](const RunResult& r, const std::string& path) {
    molchaos::io::write_xyz_file(r, path);
  });
}
