// The MPI side of schedule.hpp: rank 0 hands out case jobs as JSON text, workers send back their
// case records as JSON text. Tags: a worker's first message is kReady; each result is kResult and
// asks for the next job; rank 0 answers kJob or kStop.
#include <mpi.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "core/errors.hpp"
#include "sweep/schedule.hpp"

namespace gearsim::sweep {
namespace {

using json = nlohmann::ordered_json;

enum Tag : int { kReady = 1, kResult = 2, kJob = 3, kStop = 4 };
// How long rank 0 sleeps between polls for a worker's message, ms: short beside a case (~1 s),
// long enough that rank 0 leaves the cores to the workers (a blocking MPI receive spins).
constexpr int kMasterPoll_ms = 2;

void send_text(const std::string& text, int to, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

// The next message from `from` (or any rank): its text, source and tag. With `poll`, sleeps
// between MPI_Iprobe calls instead of blocking in a spinning receive.
std::string receive_text(int from, bool poll, int& source, int& tag) {
  MPI_Status status;
  if (poll) {
    int flag = 0;
    while (MPI_Iprobe(from, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status), !flag)
      std::this_thread::sleep_for(std::chrono::milliseconds(kMasterPoll_ms));
  } else {
    MPI_Probe(from, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
  }
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::string text(static_cast<std::size_t>(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  source = status.MPI_SOURCE;
  tag = status.MPI_TAG;
  return text;
}

bool env_above_one(const char* name) {
  const char* v = std::getenv(name);
  return v && std::atoi(v) > 1;
}

}  // namespace

bool mpi_requested() { return env_above_one("OMPI_COMM_WORLD_SIZE") || env_above_one("PMI_SIZE"); }

MpiSession::MpiSession() {
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

std::vector<CaseRecord> run_mpi_master(const std::vector<CaseJob>& jobs, const ProgressFn& progress, const std::function<int()>& stop) {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const auto start = std::chrono::steady_clock::now();
  std::vector<CaseRecord> records;
  Progress p;
  p.to_run = jobs.size();
  std::size_t next = 0;
  for (int active = size - 1; active > 0;) {
    int source = 0, tag = 0;
    const std::string text = receive_text(MPI_ANY_SOURCE, true, source, tag);
    if (tag == kResult) {
      records.push_back(case_record_from_json(json::parse(text), "the record from MPI rank " + std::to_string(source)));
      count_finished(p, records.back(), start, progress);
    }
    // The asking worker gets the next case, or stop.
    if (next < jobs.size() && !(stop && stop() != 0)) {
      send_text(case_job_json(jobs[next++]).dump(), source, kJob);
    } else {
      send_text("", source, kStop);
      --active;
    }
  }
  return records;
}

void run_mpi_worker(const CaseContext& context) {
  send_text("", 0, kReady);
  while (true) {
    int source = 0, tag = 0;
    const std::string text = receive_text(0, false, source, tag);
    if (tag == kStop) return;
    if (tag != kJob) throw InternalError("sweep: MPI message with tag " + std::to_string(tag) + " from rank 0");
    const CaseRecord r = run_case(case_job_from_json(json::parse(text)), context);
    send_text(case_record_json(r).dump(), 0, kResult);
  }
}

}  // namespace gearsim::sweep
