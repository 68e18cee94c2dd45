#include "analysis/fft.hpp"

#include <fftw3.h>

#include <algorithm>
#include <limits>
#include <mutex>
#include <string>

#include "core/errors.hpp"

namespace gearsim {
namespace {

// FFTW's planner is not thread-safe (fftw_execute is); every plan is made and freed under this.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

// fftw_malloc'ed buffer: FFTW's own alignment, the same on every call, so plans stay identical.
template <typename T>
struct FftwBuffer {
  explicit FftwBuffer(std::size_t n) : data(static_cast<T*>(fftw_malloc(sizeof(T) * n))) {
    GEARSIM_CHECK(data != nullptr, "fftw_malloc of " + std::to_string(n) + " elements failed");
  }
  ~FftwBuffer() { fftw_free(data); }
  FftwBuffer(const FftwBuffer&) = delete;
  FftwBuffer& operator=(const FftwBuffer&) = delete;
  T* data;
};

}  // namespace

std::vector<std::complex<double>> real_dft(const std::vector<double>& x, std::size_t fft_length) {
  if (x.empty()) throw InputError("real_dft: expected at least one sample, got none");
  if (fft_length < x.size())
    throw InputError("real_dft: fft length " + std::to_string(fft_length) + " is shorter than the record (" + std::to_string(x.size()) +
                     " samples)");
  if (fft_length > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw InputError("real_dft: fft length " + std::to_string(fft_length) + " exceeds FFTW's int range");
  const std::size_t bins = fft_length / 2 + 1;
  FftwBuffer<double> in(fft_length);
  FftwBuffer<fftw_complex> out(bins);
  fftw_plan plan;
  {
    std::lock_guard<std::mutex> lock(planner_mutex());
    plan = fftw_plan_dft_r2c_1d(static_cast<int>(fft_length), in.data, out.data, FFTW_ESTIMATE);
  }
  GEARSIM_CHECK(plan != nullptr, "FFTW could not plan a length-" + std::to_string(fft_length) + " DFT");
  // Planning with ESTIMATE leaves the arrays alone, so fill after planning.
  std::copy(x.begin(), x.end(), in.data);
  std::fill(in.data + x.size(), in.data + fft_length, 0.0);
  fftw_execute(plan);
  std::vector<std::complex<double>> result(bins);
  for (std::size_t k = 0; k < bins; ++k) result[k] = {out.data[k][0], out.data[k][1]};
  {
    std::lock_guard<std::mutex> lock(planner_mutex());
    fftw_destroy_plan(plan);
  }
  return result;
}

std::vector<double> real_idft(const std::vector<std::complex<double>>& X, std::size_t length) {
  if (length == 0 || X.size() != length / 2 + 1)
    throw InputError("real_idft: " + std::to_string(X.size()) + " bins do not make a length-" + std::to_string(length) + " signal");
  if (length > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw InputError("real_idft: length " + std::to_string(length) + " exceeds FFTW's int range");
  FftwBuffer<fftw_complex> in(X.size());
  FftwBuffer<double> out(length);
  fftw_plan plan;
  {
    std::lock_guard<std::mutex> lock(planner_mutex());
    plan = fftw_plan_dft_c2r_1d(static_cast<int>(length), in.data, out.data, FFTW_ESTIMATE);
  }
  GEARSIM_CHECK(plan != nullptr, "FFTW could not plan a length-" + std::to_string(length) + " inverse DFT");
  for (std::size_t k = 0; k < X.size(); ++k) in.data[k][0] = X[k].real(), in.data[k][1] = X[k].imag();
  fftw_execute(plan);  // c2r overwrites its input; it is ours
  std::vector<double> result(out.data, out.data + length);
  for (double& v : result) v /= static_cast<double>(length);
  {
    std::lock_guard<std::mutex> lock(planner_mutex());
    fftw_destroy_plan(plan);
  }
  return result;
}

}  // namespace gearsim
