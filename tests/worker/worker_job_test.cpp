// `aerobreak worker` as the orchestrator runs it: real mpirun jobs over the real binary, driven
// through their stdin and stdout (docs/WORKER_PROTOCOL.md).
#include <catch2/catch.hpp>

#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <system_error>
#include <thread>

#include "engine/impact/impact_result.hpp"
#include "engine/io/h5md_reader.hpp"
#include "orchestrator/worker/worker_protocol.hpp"
#include "worker_cases.hpp"
#include "worker_job.hpp"

using namespace aerobreak;
using namespace aerobreak::testing;
using Catch::Matchers::Contains;

namespace {

// Generous for a loaded machine; a job that works answers within a second or two.
constexpr double kPatience = 20.0;

// Sends stop and checks that the job ends with status 0 and says nothing more.
void stop_cleanly(WorkerJob& job) {
  job.send(stop_message());
  INFO("stderr of the job:\n" << job.stderr_text());
  const std::optional<Json> extra = job.next_message(kPatience);
  CHECK_FALSE(extra.has_value());
  CHECK(job.wait_exit(kPatience) == 0);
}

// The answer to one case after its "started" message.
Json answer_of(WorkerJob& job, std::int64_t id, const std::string& type) {
  const Json started = job.expect("started", kPatience);
  CHECK(started["case"] == id);
  const Json answer = job.expect(type, kPatience);
  CHECK(answer["case"] == id);
  CHECK(answer["rank"] == started["rank"]);
  return answer;
}

// The process of a rank other than rank 0 (whose pid the ready message gives) of `job`.
pid_t worker_rank_process(const WorkerJob& job, pid_t rank0) {
  for (pid_t p : processes_with_marker(job.marker())) {
    std::ifstream comm("/proc/" + std::to_string(p) + "/comm");
    std::string name;
    std::getline(comm, name);
    if (p != job.pid() && p != rank0 && name == "aerobreak") return p;
  }
  return -1;
}

struct Scratch {
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("aerobreak_worker_job_" + std::to_string(::getpid()));
  Scratch() { std::filesystem::create_directories(dir); }
  ~Scratch() {
    std::error_code ignored;
    std::filesystem::remove_all(dir, ignored);
  }
};

}  // namespace

TEST_CASE("A two-rank job answers every case, passes cheap cases past a costly one, and stops cleanly") {
  WorkerJob job(2);
  const Json ready = job.expect("ready", kPatience);
  CHECK(ready["ranks"] == 2);
  CHECK(ready["hosts"].size() == 2);
  CHECK(ready["pid"].get<std::int64_t>() > 0);
  CHECK_FALSE(ready["version"].get<std::string>().empty());

  job.send(case_message(1, slow_case(1e5)));  // about 3 s
  job.send(case_message(2, tiny_case()));
  job.send(case_message(3, tiny_case()));
  job.send(stop_message());  // the cases sent before it are still run and answered

  std::map<std::int64_t, Json> started, results;
  std::vector<std::int64_t> finished;
  while (results.size() < 3) {
    const std::optional<Json> message = job.next_message(kPatience);
    INFO("stderr of the job:\n" << job.stderr_text());
    REQUIRE(message.has_value());
    INFO("message: " << message->dump());
    const std::int64_t id = (*message)["case"];
    if ((*message)["type"] == "started") {
      CHECK(started.count(id) == 0);
      started[id] = *message;
    } else {
      REQUIRE((*message)["type"] == "result");
      REQUIRE(started.count(id) == 1);
      CHECK((*message)["rank"] == started[id]["rank"]);
      results[id] = *message;
      finished.push_back(id);
    }
  }
  CHECK(finished.back() == 1);                      // the cheap cases did not wait behind the costly one ...
  CHECK(results[2]["rank"] == results[3]["rank"]);  // ... but went to the other rank
  CHECK(results[1]["rank"] != results[2]["rank"]);
  for (const auto& [id, message] : results) {
    INFO("case " << id);
    CHECK(message["attempt"] == 0);
    CHECK(message["seconds"].get<double>() > 0.0);
    CHECK(message["data_file"] == "");
    CHECK(validate_result(message["result"]).empty());
    CHECK(started[id]["host"] == ready["hosts"][started[id]["rank"].get<std::size_t>()]);
  }
  INFO("stderr of the job:\n" << job.stderr_text());
  CHECK(job.wait_exit(kPatience) == 0);
  CHECK_FALSE(job.next_message(1.0).has_value());
}

TEST_CASE("An invalid case fails as invalid, naming the field, and the job carries on") {
  WorkerJob job(2);
  job.expect("ready", kPatience);
  Json document = tiny_case();
  document["impact"]["speed"] = -1.0;
  job.send(case_message(11, document));
  const Json failed = answer_of(job, 11, "failed");
  CHECK(failed["kind"] == "invalid");
  CHECK_THAT(failed["error"].get<std::string>(), Contains("/impact/speed"));

  job.send(case_message(12, tiny_case()));
  answer_of(job, 12, "result");
  stop_cleanly(job);
}

TEST_CASE("A case past its wall time fails as wall_time within a few seconds") {
  WorkerJob job(2);
  job.expect("ready", kPatience);
  const auto sent = Clock::now();
  job.send(case_message(21, slow_case(1e6), 0.5));  // about 30 s without the limit
  const Json failed = answer_of(job, 21, "failed");
  CHECK(seconds_since(sent) < 5.0);
  CHECK(failed["kind"] == "wall_time");
  CHECK(failed["seconds"].get<double>() >= 0.5);
  CHECK(failed["seconds"].get<double>() < 3.0);
  stop_cleanly(job);
}

TEST_CASE("stdin ending without a stop ends the whole job at once, leaving no process behind") {
  WorkerJob job(2);
  job.expect("ready", kPatience);
  job.send(case_message(31, slow_case(1e6)));  // about 30 s
  job.expect("started", kPatience);
  CHECK_FALSE(processes_with_marker(job.marker()).empty());  // the marker does find the job

  const auto closed = Clock::now();
  job.close_stdin();
  const std::optional<int> status = job.wait_exit(10.0);
  REQUIRE(status.has_value());
  CHECK(*status != 0);
  CHECK(seconds_since(closed) < 10.0);
  // The ranks may be reaped a moment after mpirun returns.
  while (!processes_with_marker(job.marker()).empty() && seconds_since(closed) < 15.0)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  CHECK(processes_with_marker(job.marker()).empty());
}

TEST_CASE("A case with a data file writes the first and last states under that name only") {
  Scratch scratch;
  const std::filesystem::path data_file = scratch.dir / "not" / "yet" / "there" / "case41.h5";
  WorkerJob job(2);
  job.expect("ready", kPatience);
  job.send(case_message(41, tiny_case(), 0.0, data_file.string()));
  const Json result = answer_of(job, 41, "result");
  CHECK(result["data_file"] == data_file.string());
  REQUIRE(std::filesystem::exists(data_file));
  for (const auto& entry : std::filesystem::directory_iterator(data_file.parent_path()))
    CHECK(entry.path() == data_file);  // nothing half-written left beside it
  REQUIRE(h5md_frame_count(data_file) == 2);
  CHECK(read_h5md_frame(data_file, 0).position.size() == 16);
  CHECK(read_h5md_frame(data_file, 1).position.size() == 16);
  stop_cleanly(job);
}

TEST_CASE("A line that is no message gets a protocol_error and the job carries on") {
  WorkerJob job(2);
  job.expect("ready", kPatience);
  job.send_line("@aerobreak {\"type\": \"case\", this is not JSON");
  CHECK_THAT(job.expect("protocol_error", kPatience)["message"].get<std::string>(), Contains("not JSON"));
  job.send_line("a line without the prefix");
  CHECK_THAT(job.expect("protocol_error", kPatience)["message"].get<std::string>(), Contains("prefix"));

  job.send(case_message(51, tiny_case()));
  answer_of(job, 51, "result");
  stop_cleanly(job);
}

TEST_CASE("Started without mpirun, the worker is a job of one rank") {
  WorkerJob job(1, Launch::direct);
  const Json ready = job.expect("ready", kPatience);
  CHECK(ready["ranks"] == 1);
  job.send(case_message(61, tiny_case()));
  job.send(case_message(62, tiny_case()));
  CHECK(answer_of(job, 61, "result")["rank"] == 0);
  CHECK(answer_of(job, 62, "result")["rank"] == 0);
  stop_cleanly(job);
}

TEST_CASE("A running job says it is alive every couple of seconds") {
  WorkerJob job(2);
  job.expect("ready", kPatience);
  job.send(case_message(81, slow_case(1e6), 5.0));  // stopped by its wall time after 5 s
  CHECK(answer_of(job, 81, "failed")["kind"] == "wall_time");
  CHECK(job.heartbeats() >= 5 / kHeartbeatInterval.count());
  stop_cleanly(job);
}

TEST_CASE("A rank stopped before it takes its case is given up too: the hand-over never waits for the rank") {
  WorkerJob job(2, Launch::mpirun, {"--silence-limit", "2"});
  const pid_t rank0 = job.expect("ready", kPatience)["pid"].get<pid_t>();
  const pid_t rank1 = worker_rank_process(job, rank0);
  REQUIRE(rank1 > 0);
  REQUIRE(::kill(rank1, SIGSTOP) == 0);  // stopped before its first case reaches it
  job.send(case_message(73, tiny_case()));
  CHECK(job.expect("started", kPatience)["rank"] == 1);
  CHECK(job.expect("rank_lost", kPatience)["rank"] == 1);
  const Json failed = job.expect("failed", kPatience);
  CHECK(failed["case"] == 73);
  CHECK(failed["kind"] == "lost");
  job.send(case_message(74, tiny_case()));
  CHECK(answer_of(job, 74, "result")["rank"] == 0);
}

TEST_CASE("A rank stopped mid-case is given up after the silence limit: its case fails as lost, the others go on") {
  WorkerJob job(2, Launch::mpirun, {"--silence-limit", "2"});
  const pid_t rank0 = job.expect("ready", kPatience)["pid"].get<pid_t>();
  job.send(case_message(71, slow_case(1e6), 60.0));
  const Json started = job.expect("started", kPatience);
  REQUIRE(started["rank"] == 1);  // the broker hands out to the other ranks first
  const pid_t rank1 = worker_rank_process(job, rank0);
  REQUIRE(rank1 > 0);
  const auto stopped = Clock::now();
  REQUIRE(::kill(rank1, SIGSTOP) == 0);  // as a rank that hangs on a remote node

  const Json lost = job.expect("rank_lost", kPatience);
  CHECK(lost["rank"] == 1);
  CHECK(lost["ranks"] == 1);
  CHECK(lost["silent_seconds"].get<double>() >= 2.0);
  const Json failed = job.expect("failed", kPatience);
  CHECK(failed["case"] == 71);
  CHECK(failed["kind"] == "lost");
  CHECK_THAT(failed["error"].get<std::string>(), Contains("rank 1") && Contains("sent nothing"));
  CHECK(seconds_since(stopped) < 2.0 + kPatience);

  job.send(case_message(72, tiny_case()));  // the job goes on with the rank it has left
  CHECK(answer_of(job, 72, "result")["rank"] == 0);
  // A stop then ends the job without waiting for the stopped rank (MPI_Finalize would).
  job.send(stop_message());
  const std::optional<int> status = job.wait_exit(kPatience);
  REQUIRE(status.has_value());
  CHECK(*status != 0);
  const auto ended = Clock::now();
  while (!processes_with_marker(job.marker()).empty() && seconds_since(ended) < 15.0)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  CHECK(processes_with_marker(job.marker()).empty());
}
