#include "sim/step_log_reader.hpp"

#include <hdf5.h>

#include <limits>

#include <sstream>

#include "core/errors.hpp"
#include "core/input_file.hpp"

namespace gearsim::sim {
namespace {

struct File {
  hid_t id = -1;
  ~File() {
    if (id >= 0) H5Fclose(id);
  }
};

template <class T>
std::vector<T> read_column(hid_t file, const std::filesystem::path& path, const std::string& name, hid_t type) {
  const hid_t d = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  if (d < 0) throw InputError(path.string() + ": no dataset '" + name + "' (not a gearsim step log?)");
  const hid_t space = H5Dget_space(d);
  std::vector<T> out(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  const herr_t status = out.empty() ? 0 : H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  H5Sclose(space);
  H5Dclose(d);
  if (status < 0) throw InputError(path.string() + ": cannot read dataset '" + name + "'");
  return out;
}

std::string string_attribute(hid_t file, const std::filesystem::path& path, const char* name) {
  const hid_t attr = H5Aopen(file, name, H5P_DEFAULT);
  if (attr < 0) throw InputError(path.string() + ": no attribute '" + name + "' (not a gearsim step log?)");
  const hid_t type = H5Aget_type(attr);
  std::string value(H5Tget_size(type), '\0');
  H5Aread(attr, type, value.data());
  H5Tclose(type);
  H5Aclose(attr);
  value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
  return value;
}

// Each row's step time: time_step_s added step times, the sum the World keeps (world.time_s()),
// so a step's time here is bit for bit the one state.csv and contacts.csv were sampled at.
std::vector<double> step_times(const std::vector<std::int64_t>& step, double dt, const std::filesystem::path& path) {
  std::vector<double> t(step.size());
  std::int64_t k = 0;
  double time = 0;
  for (std::size_t c = 0; c < step.size(); ++c) {
    if (step[c] < k)
      throw InputError(path.string() + ": contact row " + std::to_string(c) + " has step " + std::to_string(step[c]) + " after step " +
                       std::to_string(k) + " (a damaged log)");
    for (; k < step[c]; ++k) time += dt;
    t[c] = time;
  }
  return t;
}

}  // namespace

StepLogContacts read_step_log_contacts(const std::filesystem::path& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported through our exceptions
  // Any size a run can write (≈ 50 MB per simulated second), but a regular file: a FIFO or a
  // device under the log's name would block HDF5's open or feed it without end.
  check_input_file(path, std::numeric_limits<std::size_t>::max(), "an HDF5 step log");
  File f;
  f.id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f.id < 0) throw InputError(path.string() + ": cannot open as HDF5");
  StepLogContacts c;
  const hid_t attr = H5Aopen(f.id, "time_step_s", H5P_DEFAULT);
  if (attr < 0) throw InputError(path.string() + ": no attribute 'time_step_s' (not a gearsim step log?)");
  H5Aread(attr, H5T_NATIVE_DOUBLE, &c.time_step_s);
  H5Aclose(attr);
  std::stringstream pairs(string_attribute(f.id, path, "pairs"));
  for (std::string p; std::getline(pairs, p, ',');) c.pairs.push_back(p);
  // Any stored integer or floating-point type reads into these (HDF5 converts): format 2 stores
  // narrow ints and float32, format 1 int64 and float64.
  c.normal_impulse_N_s = read_column<double>(f.id, path, "contacts/normal_impulse_N_s", H5T_NATIVE_DOUBLE);
  c.step = read_column<std::int64_t>(f.id, path, "contacts/step", H5T_NATIVE_INT64);
  c.pair = read_column<std::int64_t>(f.id, path, "contacts/pair", H5T_NATIVE_INT64);
  c.tooth_a = read_column<std::int64_t>(f.id, path, "contacts/tooth_a", H5T_NATIVE_INT64);
  c.tooth_b = read_column<std::int64_t>(f.id, path, "contacts/tooth_b", H5T_NATIVE_INT64);
  c.flank_a = read_column<std::int64_t>(f.id, path, "contacts/flank_a", H5T_NATIVE_INT64);
  if (H5Lexists(f.id, "contacts/time_s", H5P_DEFAULT) > 0)  // format 1 stored every row's time
    c.time_s = read_column<double>(f.id, path, "contacts/time_s", H5T_NATIVE_DOUBLE);
  else
    c.time_s = step_times(c.step, c.time_step_s, path);
  const std::size_t n = c.time_s.size();
  if (c.normal_impulse_N_s.size() != n || c.step.size() != n || c.pair.size() != n || c.tooth_a.size() != n || c.tooth_b.size() != n ||
      c.flank_a.size() != n)
    throw InputError(path.string() + ": the /contacts columns differ in length (a damaged log)");
  for (std::int64_t p : c.pair)
    if (p < 0 || p >= static_cast<std::int64_t>(c.pairs.size()))
      throw InputError(path.string() + ": a contact names pair " + std::to_string(p) + " of " + std::to_string(c.pairs.size()));
  return c;
}

}  // namespace gearsim::sim
