// Whole-process start-up of sightline-cli (the front binary) against sightline-cli-full (every
// module linked) on the same command line: `--help`, and `info` of tum_fr1_desk. Each iteration
// forks and execs both, output to /dev/null; the time is the front's wall time to exit, the
// counters give both means (ms) and full/front. Skipped (with a message) when the data is absent.
// Run: build/bin/bench_cli_startup --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

namespace sightline {
namespace {

std::string DataPath(const std::string& name) {
  const char* env = std::getenv("SIGHTLINE_DATA_DIR");
  return std::string(env ? env : SIGHTLINE_DEFAULT_DATA_DIR) + "/" + name;
}

// Runs `program args...` with stdout and stderr to /dev/null; the wall time until it exits in
// seconds, or -1 when it could not run or exited with a non-zero code.
double RunSeconds(const std::string& program, const std::vector<std::string>& args) {
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
    execv(program.c_str(), argv.data());
    _exit(127);
  }
  if (pid < 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return -1;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? seconds : -1;
}

void RunPair(benchmark::State& state, const std::vector<std::string>& args) {
  const std::string front = std::string(SIGHTLINE_BIN_DIR) + "/sightline-cli";
  const std::string full = std::string(SIGHTLINE_BIN_DIR) + "/sightline-cli-full";
  double front_total = 0, full_total = 0;
  for (auto _ : state) {
    const double front_s = RunSeconds(front, args);
    const double full_s = RunSeconds(full, args);
    if (front_s < 0 || full_s < 0) {
      state.SkipWithError(("sightline-cli or sightline-cli-full failed on: " + args[0]).c_str());
      return;
    }
    state.SetIterationTime(front_s);
    front_total += front_s;
    full_total += full_s;
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["front_ms"] = 1e3 * front_total / n;
  state.counters["full_ms"] = 1e3 * full_total / n;
  state.counters["full/front"] = full_total / front_total;
}

void BM_Help(benchmark::State& state) { RunPair(state, {"--help"}); }

void BM_InfoTumFr1Desk(benchmark::State& state) {
  const std::string path = DataPath("tum_fr1_desk");
  struct stat st;
  if (stat(path.c_str(), &st) != 0) {
    state.SkipWithError((path + " not found; set SIGHTLINE_DATA_DIR").c_str());
    return;
  }
  RunPair(state, {"info", path});
}

// The fastest repetition beside the median: on a loaded machine the minimum is the closest to
// what the programs cost themselves.
double Min(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

BENCHMARK(BM_Help)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0)
    ->ComputeStatistics("min", Min);
BENCHMARK(BM_InfoTumFr1Desk)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0)
    ->ComputeStatistics("min", Min);

}  // namespace
}  // namespace sightline
