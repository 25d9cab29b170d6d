// Reads the /parameters attributes of an H5MD file written by write_h5md_file (h5md_writer.cpp):
// numbers as numbers (flags as 0/1), lists as arrays, choices as fixed-length strings.
#include "molchaos/io/h5md_parameters.hpp"

#include <hdf5.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "hdf5_handle.hpp"
#include "molchaos/sim/parameter_table.hpp"

namespace molchaos::io {
namespace {

using detail::Handle;

// HDF5's own error printing off while in scope: a failure is reported once, as the exception.
class QuietErrors {
 public:
  QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;
  ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

class AttributeReader {
 public:
  AttributeReader(hid_t group, const std::string& path, const std::string& name)
      : attribute_(H5Aopen(group, name.c_str(), H5P_DEFAULT), H5Aclose), path_(path), name_(name) {
    if (attribute_.id < 0) fail("cannot be opened");
  }

  // The values as `memory_type`; the file's type must be of `kind` (HDF5 would otherwise
  // convert a string or truncate a double without a word).
  template <class T>
  std::vector<T> numbers(hid_t memory_type, H5T_class_t kind) {
    require_class(kind, kind == H5T_FLOAT ? "a floating-point number" : "an integer");
    std::vector<T> values(points());
    if (!values.empty() && H5Aread(attribute_.id, memory_type, values.data()) < 0)
      fail("cannot be read");
    return values;
  }

  // One string, fixed-length (as the writer stores it) or variable-length (as h5py does).
  std::string text() {
    require_class(H5T_STRING, "a string");
    if (points() != 1) fail("is not one string");
    const Handle type(H5Aget_type(attribute_.id), H5Tclose);
    const Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_cset(memory.id, H5Tget_cset(type.id));  // ASCII or UTF-8: HDF5 converts neither way
    if (H5Tis_variable_str(type.id) > 0) {
      H5Tset_size(memory.id, H5T_VARIABLE);
      char* value = nullptr;
      if (H5Aread(attribute_.id, memory.id, &value) < 0 || value == nullptr) fail("cannot be read");
      std::string text(value);
      H5free_memory(value);
      return text;
    }
    std::string value(H5Tget_size(type.id), '\0');
    H5Tset_size(memory.id, value.size());
    if (!value.empty() && H5Aread(attribute_.id, memory.id, value.data()) < 0)
      fail("cannot be read");
    return value;
  }

  // Whether the file stores the attribute as a signed integer.
  bool is_signed() const {
    const Handle type(H5Aget_type(attribute_.id), H5Tclose);
    return H5Tget_class(type.id) == H5T_INTEGER && H5Tget_sign(type.id) == H5T_SGN_2;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(path_ + ": attribute /parameters/" + name_ + " " + what);
  }

 private:
  std::size_t points() {
    const Handle space(H5Aget_space(attribute_.id), H5Sclose);
    const hssize_t n = H5Sget_simple_extent_npoints(space.id);
    if (n < 0) fail("has no readable shape");
    return static_cast<std::size_t>(n);
  }

  void require_class(H5T_class_t kind, const char* what) {
    const Handle type(H5Aget_type(attribute_.id), H5Tclose);
    if (H5Tget_class(type.id) != kind) fail(std::string("is not ") + what);
  }

  Handle attribute_;
  std::string path_;
  std::string name_;
};

// The text values of one row, read as the writer stores the row's type.
std::vector<std::string> row_values(AttributeReader& reader, const sim::ParameterInfo& info) {
  return std::visit(
      [&](auto member) -> std::vector<std::string> {
        using T = std::remove_cvref_t<decltype(sim::Parameters{}.*member)>;
        std::vector<std::string> texts;
        if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::vector<double>>) {
          for (double x : reader.numbers<double>(H5T_NATIVE_DOUBLE, H5T_FLOAT))
            texts.push_back(sim::round_trip_text(x));
          if (std::is_same_v<T, double> && texts.size() != 1) reader.fail("is not one number");
        } else if constexpr (std::is_same_v<T, std::uint64_t>) {
          // A signed attribute (h5py stores a Python int as int64) is read as one: HDF5's
          // conversion to uint64 would clip a negative value to 0 without a word.
          if (reader.is_signed()) {
            for (std::int64_t x : reader.numbers<std::int64_t>(H5T_NATIVE_INT64, H5T_INTEGER)) {
              if (x < 0)
                reader.fail("is " + std::to_string(x) + ", outside the allowed range [0, " +
                            std::to_string(std::numeric_limits<std::uint64_t>::max()) + "]");
              texts.push_back(std::to_string(x));
            }
          } else {
            for (std::uint64_t x : reader.numbers<std::uint64_t>(H5T_NATIVE_UINT64, H5T_INTEGER))
              texts.push_back(std::to_string(x));
          }
          if (texts.size() != 1) reader.fail("is not one number");
        } else if constexpr (std::is_same_v<T, bool>) {
          const auto values = reader.numbers<std::int64_t>(H5T_NATIVE_INT64, H5T_INTEGER);
          if (values.size() != 1 || (values[0] != 0 && values[0] != 1))
            reader.fail("is not one flag, 0 or 1");
          texts.push_back(values[0] != 0 ? "true" : "false");
        } else if constexpr (std::is_integral_v<T>) {
          for (std::int64_t x : reader.numbers<std::int64_t>(H5T_NATIVE_INT64, H5T_INTEGER))
            texts.push_back(std::to_string(x));
          if (texts.size() != 1) reader.fail("is not one number");
        } else {  // a choice, by name
          texts.push_back(reader.text());
        }
        return texts;
      },
      info.field);
}

}  // namespace

std::vector<std::pair<std::string, std::vector<std::string>>> read_h5md_parameters(
    const std::string& path) {
  const QuietErrors quiet;
  const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (file.id < 0) throw std::runtime_error(path + ": cannot be opened as an HDF5 file");
  if (H5Lexists(file.id, "parameters", H5P_DEFAULT) <= 0)
    throw std::runtime_error(path + ": no /parameters group (not a molchaos trajectory)");
  const Handle group(H5Gopen2(file.id, "parameters", H5P_DEFAULT), H5Gclose);
  if (group.id < 0) throw std::runtime_error(path + ": /parameters is not a group");
  // An attribute the writer does not write (a parameter of another version, a misspelt name added
  // by hand) is refused, as an unknown key of a CSV header is: its value would be dropped.
  std::vector<std::string> names;
  H5Aiterate2(
      group.id, H5_INDEX_NAME, H5_ITER_INC, nullptr,
      [](hid_t, const char* name, const H5A_info_t*, void* out) -> herr_t {
        static_cast<std::vector<std::string>*>(out)->emplace_back(name);
        return 0;
      },
      &names);
  for (const std::string& name : names)
    if (sim::find_parameter(name) == nullptr && name != "stop_reason" && name != "version")
      throw std::runtime_error(path + ": attribute /parameters/" + name +
                               " names no parameter of this version");
  // The writer puts only attributes there: a group or dataset (a parameter stored as a dataset in
  // place of its attribute) would be passed over.
  hsize_t objects = 0;
  H5G_info_t group_info;
  if (H5Gget_info(group.id, &group_info) >= 0) objects = group_info.nlinks;
  if (objects > 0) {
    char name[256] = {};
    H5Lget_name_by_idx(group.id, ".", H5_INDEX_NAME, H5_ITER_INC, 0, name, sizeof name - 1,
                       H5P_DEFAULT);
    throw std::runtime_error(path + ": /parameters holds " + std::to_string(objects) +
                             " group(s) or dataset(s), such as '" + name +
                             "'; the run's parameters are its attributes");
  }
  std::vector<std::pair<std::string, std::vector<std::string>>> items;
  for (const sim::ParameterInfo& info : sim::parameter_table()) {
    const std::string name(info.name);
    if (H5Aexists(group.id, name.c_str()) <= 0) continue;
    AttributeReader reader(group.id, path, name);
    items.emplace_back(name, row_values(reader, info));
  }
  return items;
}

}  // namespace molchaos::io
