// An HDF5 identifier that closes itself: the writer and the reader of H5MD files hold every file,
// group, dataset, attribute, dataspace, datatype and property list they open in one, so that an
// exception on the way out (a failed write, a malformed file) leaks none of them.
#pragma once

#include <hdf5.h>

namespace molchaos::io::detail {

// Closes the id at scope exit with the close function of its kind (H5Fclose, H5Gclose, ...).
// A negative id, a failed open or create, is not closed.
struct Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  Handle(hid_t id_, herr_t (*close_)(hid_t)) : id(id_), close(close_) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (id >= 0) close(id);
  }
};

}  // namespace molchaos::io::detail
