// sweep.h5: the gathered table in HDF5 (table.hpp).
#include <hdf5.h>

#include <cerrno>
#include <cstring>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include "core/errors.hpp"
#include "sweep/table.hpp"
#include "core/output_file.hpp"

namespace gearsim::sweep {
namespace {

// A 1-D dataset of `n` values of `type` (no timestamps: the same table gives the same bytes).
// Closes a file whose writes failed without writing more (HDF5 would flush its metadata, and
// crash at exit when that fails); its StagedPath removes it.
void close_unwritten(hid_t h5) {
  void* handle = nullptr;
  if (H5Fget_vfd_handle(h5, H5P_DEFAULT, &handle) >= 0 && handle) divert_to_null(*static_cast<int*>(handle));
  H5Fclose(h5);
}

void write_dataset(hid_t group, const std::string& name, hid_t type, std::size_t n, const void* data, const std::filesystem::path& file) {
  const hsize_t dims[1] = {n};
  const hid_t space = H5Screate_simple(1, dims, nullptr);
  const hid_t props = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_obj_track_times(props, false);
  const hid_t set = H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, props, H5P_DEFAULT);
  const herr_t status = set < 0 ? -1 : H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  if (set >= 0) H5Dclose(set);
  H5Pclose(props);
  H5Sclose(space);
  if (status < 0) throw OutputError(file.string() + ": cannot write the dataset '" + name + "': " + std::strerror(errno ? errno : EIO));
}

void write_strings(hid_t group, const std::string& name, const std::vector<std::string>& values, const std::filesystem::path& file) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  std::vector<const char*> ptrs;
  for (const std::string& v : values) ptrs.push_back(v.c_str());
  write_dataset(group, name, type, values.size(), ptrs.data(), file);
  H5Tclose(type);
}

void write_doubles(hid_t group, const std::string& name, const std::vector<double>& values, const std::filesystem::path& file) {
  write_dataset(group, name, H5T_NATIVE_DOUBLE, values.size(), values.data(), file);
}

// A parameter column: numbers when every value reads as one, else its texts.
void write_parameter(hid_t group, const SweepTable& t, std::size_t k, const std::filesystem::path& file) {
  std::vector<double> numbers;
  std::vector<std::string> texts;
  bool numeric = true;
  for (const TableRow& r : t.rows) {
    const std::string& v = r.parameters[k];
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    numeric = numeric && !v.empty() && end == v.c_str() + v.size();
    numbers.push_back(x);
    texts.push_back(v);
  }
  if (numeric)
    write_doubles(group, t.parameter_columns[k], numbers, file);
  else
    write_strings(group, t.parameter_columns[k], texts, file);
}

}  // namespace

void write_table_h5(const SweepTable& t, const std::filesystem::path& file) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported through our exceptions
  const hid_t props = H5Pcreate(H5P_FILE_CREATE);
  StagedPath staged(file, Durability::Record);  // put in place whole (core/output_file.hpp)
  const hid_t h5 = H5Fcreate(staged.temp().c_str(), H5F_ACC_EXCL, props, H5P_DEFAULT);
  H5Pclose(props);
  if (h5 < 0) throw OutputError(file.string() + ": cannot create the HDF5 file: " + std::strerror(errno));
  const hid_t group_props = H5Pcreate(H5P_GROUP_CREATE);
  H5Pset_obj_track_times(group_props, false);
  const hid_t group = H5Gcreate2(h5, "table", H5P_DEFAULT, group_props, H5P_DEFAULT);
  H5Pclose(group_props);
  try {
    std::vector<std::string> columns{"index"};
    std::vector<std::int64_t> index;
    std::vector<std::string> status;
    for (const TableRow& r : t.rows) index.push_back(static_cast<std::int64_t>(r.index)), status.push_back(r.status);
    write_dataset(group, "index", H5T_NATIVE_INT64, index.size(), index.data(), file);
    for (std::size_t k = 0; k < t.parameter_columns.size(); ++k) {
      write_parameter(group, t, k, file);
      columns.push_back(t.parameter_columns[k]);
    }
    write_strings(group, "status", status, file);
    columns.push_back("status");
    for (std::size_t m = 0; m < t.metric_columns.size(); ++m) {
      std::vector<double> values;
      for (const TableRow& r : t.rows) values.push_back(r.metrics[m].value_or(std::numeric_limits<double>::quiet_NaN()));
      write_doubles(group, t.metric_columns[m], values, file);
      columns.push_back(t.metric_columns[m]);
    }
    write_strings(group, "columns", columns, file);
  } catch (...) {
    H5Gclose(group);
    close_unwritten(h5);
    throw;
  }
  H5Gclose(group);
  if (H5Fflush(h5, H5F_SCOPE_GLOBAL) < 0) {
    const int err = errno ? errno : EIO;
    close_unwritten(h5);
    throw OutputError(file.string() + ": cannot write the HDF5 file: " + std::strerror(err));
  }
  if (H5Fclose(h5) < 0) throw OutputError(file.string() + ": cannot write the HDF5 file: " + std::strerror(errno ? errno : EIO));
  staged.commit();
}

}  // namespace gearsim::sweep
