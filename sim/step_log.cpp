#include "sim/step_log.hpp"

#include <hdf5.h>

#include <array>
#include <cstdint>
#include <vector>

#include "core/errors.hpp"

namespace gearsim::sim {
namespace {

// Rows buffered before a write, and the HDF5 chunk length: 4096 rows of 8 bytes per column is a
// 32 KiB chunk, HDF5's sweet spot for appends and deflate.
constexpr hsize_t kChunkRows = 4096;

// An extendible, chunked, deflated 1-D or 2-D dataset that grows by rows.
struct Column {
  hid_t dataset = -1;
  hid_t type = -1;
  hsize_t width = 1;  // columns per row (1 for a 1-D column)
  hsize_t rows = 0;

  void create(hid_t parent, const char* name, hid_t memtype, hsize_t row_width) {
    type = memtype;
    width = row_width;
    const int rank = width == 1 ? 1 : 2;
    const hsize_t dims[2] = {0, width}, maxdims[2] = {H5S_UNLIMITED, width}, chunk[2] = {kChunkRows, width};
    const hid_t space = H5Screate_simple(rank, dims, maxdims);
    const hid_t props = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(props, rank, chunk);
    H5Pset_shuffle(props);
    H5Pset_deflate(props, 1);
    H5Pset_obj_track_times(props, false);  // no timestamps: the same run gives the same bytes
    dataset = H5Dcreate2(parent, name, memtype, space, H5P_DEFAULT, props, H5P_DEFAULT);
    H5Pclose(props);
    H5Sclose(space);
    GEARSIM_CHECK(dataset >= 0, std::string("HDF5 dataset creation failed: ") + name);
  }

  void append(const void* data, hsize_t new_rows) {
    if (new_rows == 0) return;
    const int rank = width == 1 ? 1 : 2;
    const hsize_t size[2] = {rows + new_rows, width};
    H5Dset_extent(dataset, size);
    const hid_t file_space = H5Dget_space(dataset);
    const hsize_t start[2] = {rows, 0}, count[2] = {new_rows, width};
    H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr);
    const hid_t mem_space = H5Screate_simple(rank, count, nullptr);
    const herr_t status = H5Dwrite(dataset, type, mem_space, file_space, H5P_DEFAULT, data);
    H5Sclose(mem_space);
    H5Sclose(file_space);
    GEARSIM_CHECK(status >= 0, "HDF5 write failed");
    rows += new_rows;
  }

  void close() {
    if (dataset >= 0) H5Dclose(dataset);
    dataset = -1;
  }
};

void string_attribute(hid_t object, const char* name, const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.size() + 1);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attr, type, value.c_str());
  H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
}

void double_attribute(hid_t object, const char* name, double value) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(object, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attr, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(attr);
  H5Sclose(space);
}

}  // namespace

struct StepLog::Impl {
  std::filesystem::path path;
  hid_t file = -1, contacts_group = -1;
  Column state;
  std::vector<double> state_rows;
  // Contact columns: doubles and integers.
  static constexpr std::array<const char*, 8> kDoubleNames{"time_s", "point_x_m", "point_y_m", "normal_x", "normal_y",
                                                           "depth_m", "normal_impulse_N_s", "friction_impulse_N_s"};
  static constexpr std::array<const char*, 5> kIntNames{"step", "pair", "tooth_a", "tooth_b", "flank_a"};
  std::array<Column, 8> dcol;
  std::array<Column, 5> icol;
  std::array<std::vector<double>, 8> dbuf;
  std::array<std::vector<std::int64_t>, 5> ibuf;
  double dt = 0;

  void flush() {
    state.append(state_rows.data(), state_rows.size() / state.width);
    state_rows.clear();
    for (std::size_t c = 0; c < dcol.size(); ++c) {
      dcol[c].append(dbuf[c].data(), dbuf[c].size());
      dbuf[c].clear();
    }
    for (std::size_t c = 0; c < icol.size(); ++c) {
      icol[c].append(ibuf[c].data(), ibuf[c].size());
      ibuf[c].clear();
    }
    H5Fflush(file, H5F_SCOPE_GLOBAL);
  }
};

StepLog::StepLog(const std::filesystem::path& path, const physics::World& world, const std::string& scenario_name, double dt)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.path = path;
  m.dt = dt;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported through our exceptions
  m.file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (m.file < 0) throw InputError(path.string() + ": cannot create the HDF5 step log");
  string_attribute(m.file, "scenario", scenario_name);
  string_attribute(m.file, "units", "SI: s, m, rad, rad/s, N·s (impulses per step; force = impulse / time_step_s)");
  double_attribute(m.file, "time_step_s", dt);
  std::string columns = "time_s";
  for (const physics::BodyState& b : world.bodies()) columns += "," + b.name + "_angle_rad," + b.name + "_speed_rad_s";
  m.state.create(m.file, "state", H5T_NATIVE_DOUBLE, 1 + 2 * world.bodies().size());
  string_attribute(m.state.dataset, "columns", columns);
  std::string pairs;
  for (const physics::GearPairInfo& p : world.gear_pairs()) pairs += (pairs.empty() ? "" : ",") + p.body_a + "__" + p.body_b;
  string_attribute(m.file, "pairs", pairs);
  const hid_t group_props = H5Pcreate(H5P_GROUP_CREATE);
  H5Pset_obj_track_times(group_props, false);
  m.contacts_group = H5Gcreate2(m.file, "contacts", H5P_DEFAULT, group_props, H5P_DEFAULT);
  H5Pclose(group_props);
  for (std::size_t c = 0; c < m.dcol.size(); ++c) m.dcol[c].create(m.contacts_group, Impl::kDoubleNames[c], H5T_NATIVE_DOUBLE, 1);
  for (std::size_t c = 0; c < m.icol.size(); ++c) m.icol[c].create(m.contacts_group, Impl::kIntNames[c], H5T_NATIVE_INT64, 1);
}

StepLog::~StepLog() {
  try {
    close();
  } catch (...) {
  }
}

void StepLog::append(const physics::World& world) {
  Impl& m = *impl_;
  GEARSIM_CHECK(m.file >= 0, "StepLog::append after close");
  m.state_rows.push_back(world.time_s());
  for (const physics::BodyState& b : world.bodies()) {
    m.state_rows.push_back(b.angle_rad);
    m.state_rows.push_back(b.speed_rad_s);
  }
  for (const physics::ContactSample& c : world.contacts()) {
    const double d[8] = {world.time_s(), c.geometry.point_m.x(), c.geometry.point_m.y(), c.geometry.normal_on_b.x(),
                         c.geometry.normal_on_b.y(), c.geometry.depth_m, c.normal_force_N * m.dt, c.friction_force_N * m.dt};
    const std::int64_t i[5] = {world.steps(), c.pair, c.geometry.tooth_a, c.geometry.tooth_b,
                               c.geometry.flank_a == Flank::Ccw ? 0 : 1};
    for (std::size_t k = 0; k < 8; ++k) m.dbuf[k].push_back(d[k]);
    for (std::size_t k = 0; k < 5; ++k) m.ibuf[k].push_back(i[k]);
  }
  if (m.state_rows.size() / m.state.width >= kChunkRows) m.flush();
}

void StepLog::close() {
  Impl& m = *impl_;
  if (m.file < 0) return;
  m.flush();
  m.state.close();
  for (Column& c : m.dcol) c.close();
  for (Column& c : m.icol) c.close();
  H5Gclose(m.contacts_group);
  H5Fclose(m.file);
  m.file = -1;
}

std::uintmax_t StepLog::bytes_on_disk() const {
  std::error_code ec;
  const auto size = std::filesystem::file_size(impl_->path, ec);
  return ec ? 0 : size;
}

}  // namespace gearsim::sim
