#include "offline_common.hpp"

#include "format.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>
#include <vector>

#include "experiment.hpp"

namespace swarm::tools {

std::string make_out_dir(const std::string& requested, const std::string& fallback) {
  namespace fs = std::filesystem;
  const std::string dir = fs::absolute(requested.empty() ? "runs/" + fallback + "-" + local_timestamp(std::time(nullptr))
                                                         : requested)
                              .lexically_normal()
                              .string();
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir, ec)) {
    throw OfflineBadInput("cannot create the output directory " + dir + " (" + ec.message() +
                          "); choose a writable one with --out DIR");
  }
  return dir;
}

int picture_scale(const planner::OccupancyGrid& map) {
  return std::clamp(640 / std::max(1, std::max(map.width(), map.height())), 4, 40);
}

int finish_experiment(const std::string& dir, const ExperimentOutputs& outputs, const char* me,
                      std::ostream& out, std::ostream& err) {
  out << "\n" << outputs.table;
  try {
    (void)write_outputs(dir, outputs);
  } catch (const std::exception& e) {
    err << me << ": " << e.what() << "\n";
    return 1;
  }
  out << "written to " << dir << "\n";
  return 0;
}

void run_jobs(std::size_t n, std::size_t threads, const std::function<void(std::size_t)>& work,
              const std::function<void(std::size_t, std::size_t)>& finished) {
  std::atomic<std::size_t> next{0};
  std::mutex lock;
  std::size_t done = 0;
  std::exception_ptr failure;
  const auto loop = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      try {
        work(i);
      } catch (...) {
        const std::lock_guard<std::mutex> g(lock);
        if (!failure) failure = std::current_exception();
        next = n;  // the others stop after their current job
        return;
      }
      const std::lock_guard<std::mutex> g(lock);
      finished(i, ++done);
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < std::min(threads, n); ++t) pool.emplace_back(loop);
  loop();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace swarm::tools
