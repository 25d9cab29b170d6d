// Extended XYZ as read by ASE and OVITO: the comment line holds key=value pairs.
#include "molchaos/io/xyz_writer.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <variant>

#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/parameter_table.hpp"

namespace molchaos::io {

void write_xyz_frame(const sim::RunResult& r, std::size_t index, std::ostream& out) {
  const sim::Snapshot& s = r.snapshots.at(index);
  const int dimension = r.parameters.dimension;
  const auto d = static_cast<std::size_t>(dimension);
  const std::size_t n = s.positions.size() / d;
  const std::string L = sim::round_trip_text(s.box);
  // Disks: the third cell vector has the disk diameter as length and is not periodic.
  const std::string z = dimension == 3 ? L : "1";
  out << n << '\n'
      << "Lattice=\"" << L << " 0 0 0 " << L << " 0 0 0 " << z << "\" "
      << "Properties=species:S:1:pos:R:3:vel:R:3:momenta:R:3 Time=" << sim::round_trip_text(s.t)
      << " Collisions=" << s.collisions << " pbc=\"" << (dimension == 3 ? "T T T" : "T T F") << '"'
      << " version=" << r.version;  // --config notes a file of another version
  // The run's parameters as in a result CSV's header, a value with spaces (a list) quoted, a
  // flag as extended XYZ's logical T or F: ASE reads "false" as a string, which Python takes for
  // true (--config reads T and F back).
  for (const sim::ParameterInfo& info : sim::parameter_table()) {
    if (sim::omitted(r.parameters, info)) continue;
    std::string value = sim::format_value(r.parameters, info);
    if (std::holds_alternative<bool sim::Parameters::*>(info.field))
      value = r.parameters.*std::get<bool sim::Parameters::*>(info.field) ? "T" : "F";
    const bool quote = value.empty() || value.find(' ') != std::string::npos;
    out << ' ' << info.name << '=' << (quote ? "\"" + value + "\"" : value);
  }
  out << '\n';
  for (std::size_t i = 0; i < n; ++i) {
    out << 'X';
    for (std::size_t a = 0; a < 3; ++a)
      out << ' ' << (a < d ? sim::round_trip_text(s.positions[i * d + a]) : "0");
    std::string velocity;
    for (std::size_t a = 0; a < 3; ++a)
      velocity += ' ' + (a < d ? sim::round_trip_text(s.velocities[i * d + a]) : "0");
    // ASE takes velocities from `momenta` alone (its Atoms.get_velocities() is momenta over
    // masses, and species X has mass 1): with m = 1 they are the velocities again, so that a
    // frame read by ase.io.read moves; `vel` stays for OVITO and earlier readers.
    out << velocity << velocity << '\n';
  }
}

void write_xyz_file(const sim::RunResult& r, const std::string& path, sim::StagedFiles& files) {
  files.write(path, [&](std::ostream& out) {
    for (std::size_t k = 0; k < r.snapshots.size(); ++k) write_xyz_frame(r, k, out);
  });
}

void write_xyz_file(const sim::RunResult& r, const std::string& path) {
  sim::StagedFiles files;
  write_xyz_file(r, path, files);
  files.commit();
}

}  // namespace molchaos::io
