// H5MD 1.1 (de Buyl, Colberg, Höfling, 2014; nongnu.org/h5md/h5md.html) through the HDF5 C API.
// Every time-dependent element is a group {value [F x N x d], time [F], step [F]}. An event-driven
// run has no integration step: a frame's step is the number of collisions since t = 0.
#include "molchaos/io/h5md_writer.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "hdf5_handle.hpp"
#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/parameter_table.hpp"

namespace molchaos::io {
namespace {

using detail::Handle;

hid_t check(hid_t id, const char* what) {
  if (id < 0) throw std::runtime_error(std::string("HDF5: cannot create ") + what);
  return id;
}

void check_status(herr_t status, const char* what) {
  if (status < 0) throw std::runtime_error(std::string("HDF5: cannot write ") + what);
}

// `utf8`: the text may hold any UTF-8 (a person's name); HDF5 marks strings ASCII by default.
void string_attribute(hid_t where, const char* name, const std::string& value, bool utf8 = false) {
  Handle type{H5Tcopy(H5T_C_S1), H5Tclose};
  H5Tset_size(type.id, value.size());
  if (utf8) check_status(H5Tset_cset(type.id, H5T_CSET_UTF8), name);
  Handle space{H5Screate(H5S_SCALAR), H5Sclose};
  Handle attr{check(H5Acreate2(where, name, type.id, space.id, H5P_DEFAULT, H5P_DEFAULT), name),
              H5Aclose};
  check_status(H5Awrite(attr.id, type.id, value.c_str()), name);
}

template <class T>
void numeric_attribute(hid_t where, const char* name, hid_t type, const std::vector<T>& values,
                       bool scalar) {
  const hsize_t size = values.size();
  Handle space{scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &size, nullptr), H5Sclose};
  Handle attr{check(H5Acreate2(where, name, type, space.id, H5P_DEFAULT, H5P_DEFAULT), name),
              H5Aclose};
  check_status(H5Awrite(attr.id, type, values.data()), name);
}

// boundary = ["periodic", ...]: a fixed-length string array, one entry per dimension.
void boundary_attribute(hid_t box, int dimension) {
  const std::string periodic = "periodic";
  Handle type{H5Tcopy(H5T_C_S1), H5Tclose};
  H5Tset_size(type.id, periodic.size());
  const hsize_t size = static_cast<hsize_t>(dimension);
  Handle space{H5Screate_simple(1, &size, nullptr), H5Sclose};
  Handle attr{
      check(H5Acreate2(box, "boundary", type.id, space.id, H5P_DEFAULT, H5P_DEFAULT), "boundary"),
      H5Aclose};
  std::string all;
  for (int a = 0; a < dimension; ++a) all += periodic;
  check_status(H5Awrite(attr.id, type.id, all.data()), "boundary");
}

// A creation property list of class `kind` without object timestamps: HDF5 stamps every object
// header with its creation time by default, so the same run would give different bytes.
// The caller closes it (Handle{untimed(kind), H5Pclose}).
hid_t untimed(hid_t kind) {
  const hid_t plist = check(H5Pcreate(kind), "property list");
  if (H5Pset_obj_track_times(plist, false) < 0) {
    H5Pclose(plist);
    throw std::runtime_error("HDF5: cannot switch off object timestamps");
  }
  return plist;
}

// A dataset of the given shape. A time series (value, time, step of a time-dependent element)
// has the [variable] time dimension H5MD asks for: the first dimension unlimited, stored in
// chunks of one frame (value) or of all frames (time, step), so that a reader may append.
void dataset(hid_t where, const char* name, hid_t type, const std::vector<hsize_t>& shape,
             const void* data, bool time_series = false) {
  std::vector<hsize_t> max_shape = shape;
  if (time_series) max_shape[0] = H5S_UNLIMITED;
  Handle space{H5Screate_simple(static_cast<int>(shape.size()), shape.data(), max_shape.data()),
               H5Sclose};
  const Handle plist{untimed(H5P_DATASET_CREATE), H5Pclose};
  if (time_series) {
    std::vector<hsize_t> chunk = shape;
    chunk[0] = shape.size() > 1 ? 1 : std::max<hsize_t>(shape[0], 1);
    check_status(H5Pset_chunk(plist.id, static_cast<int>(chunk.size()), chunk.data()), name);
  }
  Handle set{
      check(H5Dcreate2(where, name, type, space.id, H5P_DEFAULT, plist.id, H5P_DEFAULT), name),
      H5Dclose};
  check_status(H5Dwrite(set.id, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name);
}

Handle group(hid_t where, const char* name) {
  const Handle plist{untimed(H5P_GROUP_CREATE), H5Pclose};
  return {check(H5Gcreate2(where, name, H5P_DEFAULT, plist.id, H5P_DEFAULT), name), H5Gclose};
}

// One time-dependent element: value (F x N x d), time (F), step (F, collisions since t = 0).
void time_series(hid_t particles, const char* name, const sim::RunResult& r, bool positions) {
  const auto d = static_cast<hsize_t>(r.parameters.dimension);
  const auto frames = static_cast<hsize_t>(r.snapshots.size());
  const auto n = static_cast<hsize_t>(r.parameters.particles);
  std::vector<double> value;
  std::vector<double> time;
  std::vector<std::int64_t> step;
  for (const sim::Snapshot& s : r.snapshots) {
    const auto& data = positions ? s.positions : s.velocities;
    value.insert(value.end(), data.begin(), data.end());
    time.push_back(s.t);
    step.push_back(static_cast<std::int64_t>(s.collisions));
  }
  Handle element = group(particles, name);
  dataset(element.id, "value", H5T_IEEE_F64LE, {frames, n, d}, value.data(), true);
  dataset(element.id, "time", H5T_IEEE_F64LE, {frames}, time.data(), true);
  dataset(element.id, "step", H5T_STD_I64LE, {frames}, step.data(), true);
}

void parameters_group(hid_t file, const sim::RunResult& r) {
  const sim::Parameters& p = r.parameters;
  Handle g = group(file, "parameters");
  // Every row of the parameter table: numbers as numbers (flags as 0/1), lists as arrays, named
  // choices as their names.
  for (const sim::ParameterInfo& info : sim::parameter_table()) {
    const std::string key(info.name);
    const char* name = key.c_str();
    std::visit(
        [&](auto member) {
          const auto& value = p.*member;
          using T = std::remove_cvref_t<decltype(value)>;
          if constexpr (std::is_same_v<T, double>)
            numeric_attribute(g.id, name, H5T_IEEE_F64LE, std::vector<double>{value}, true);
          else if constexpr (std::is_same_v<T, std::uint64_t>)
            numeric_attribute(g.id, name, H5T_STD_U64LE, std::vector<std::uint64_t>{value}, true);
          else if constexpr (std::is_integral_v<T>)  // int, int64, bool
            numeric_attribute(g.id, name, H5T_STD_I64LE,
                              std::vector<std::int64_t>{static_cast<std::int64_t>(value)}, true);
          else if constexpr (std::is_same_v<T, std::vector<double>>)
            numeric_attribute(g.id, name, H5T_IEEE_F64LE, value, false);
          else
            string_attribute(g.id, name, sim::format_value(p, info));
        },
        info.field);
  }
  string_attribute(g.id, "stop_reason", sim::stop_message(r));
  string_attribute(g.id, "version", r.version);
}

// H5MD's author is the person who ran the simulation (the program is the creator): the name in
// the environment variable MOLCHAOS_AUTHOR, else "unknown". Not the login name, which would make
// the same run's file differ from one user or machine to the next.
std::string author_name() {
  const char* name = std::getenv("MOLCHAOS_AUTHOR");
  return name != nullptr && *name != '\0' ? name : "unknown";
}

void write_contents(hid_t file, const sim::RunResult& r) {
  {
    Handle h5md = group(file, "h5md");
    numeric_attribute(h5md.id, "version", H5T_STD_I32LE, std::vector<std::int32_t>{1, 1}, false);
    Handle author = group(h5md.id, "author");
    string_attribute(author.id, "name", author_name(), /*utf8=*/true);
    Handle creator = group(h5md.id, "creator");
    string_attribute(creator.id, "name", "molchaos");
    string_attribute(creator.id, "version", r.version);
  }
  Handle particles = group(file, "particles");
  Handle all = group(particles.id, "all");
  {
    Handle box = group(all.id, "box");
    numeric_attribute(box.id, "dimension", H5T_STD_I32LE,
                      std::vector<std::int32_t>{r.parameters.dimension}, true);
    boundary_attribute(box.id, r.parameters.dimension);
    // The box is fixed: edges is a plain dataset (H5MD 1.1, "box" section).
    const double side = sim::box_side(r.parameters);
    const std::vector<double> edges(static_cast<std::size_t>(r.parameters.dimension), side);
    dataset(box.id, "edges", H5T_IEEE_F64LE, {edges.size()}, edges.data());
  }
  time_series(all.id, "position", r, true);
  time_series(all.id, "velocity", r, false);
  parameters_group(file, r);
}

}  // namespace

void write_h5md_file(const sim::RunResult& r, const std::string& path, sim::StagedFiles& files) {
  // Built in memory (HDF5's core driver, no backing file) and written as the image's bytes through
  // files, whose writes are checked: written by HDF5 itself, a full disk failed its flush and then
  // its close, and the file left open crashed the library's clean-up at exit (a segmentation
  // fault after the error message). The image costs memory as large as the trajectory's data.
  const Handle file_plist{untimed(H5P_FILE_CREATE), H5Pclose};  // the root group too
  const Handle access{H5Pcreate(H5P_FILE_ACCESS), H5Pclose};
  check_status(H5Pset_fapl_core(access.id, 1 << 20, /*backing_store=*/false), path.c_str());
  std::vector<char> image;
  {
    Handle file{check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, file_plist.id, access.id),
                      path.c_str()),
                H5Fclose};
    write_contents(file.id, r);
    check_status(H5Fflush(file.id, H5F_SCOPE_GLOBAL), path.c_str());
    const ssize_t size = H5Fget_file_image(file.id, nullptr, 0);
    if (size < 0) throw std::runtime_error("HDF5: cannot take the image of " + path);
    image.resize(static_cast<std::size_t>(size));
    if (H5Fget_file_image(file.id, image.data(), image.size()) != size)
      throw std::runtime_error("HDF5: cannot take the image of " + path);
  }
  files.write(path, [&](std::ostream& out) {
    out.write(image.data(), static_cast<std::streamsize>(image.size()));
  });
}

void write_h5md_file(const sim::RunResult& r, const std::string& path) {
  sim::StagedFiles files;
  write_h5md_file(r, path, files);
  files.commit();
}

}  // namespace molchaos::io
