#pragma once
#include <mpi.h>

#include <chrono>
#include <optional>
#include <string>
#include <string_view>

namespace aerobreak {

// Text messages between the ranks of a worker job (serialized JSON, MPI_CHAR), on
// MPI_COMM_WORLD. Only a rank's main thread may call these (MPI_THREAD_FUNNELED).

enum MessageTag : int {
  kTagCase = 1,    // rank 0 -> worker rank: a serialized case assignment
  kTagStop = 2,    // rank 0 -> worker rank: no more cases (empty)
  kTagAnswer = 3,  // worker rank -> rank 0: the serialized result or failed message
  kTagAlive = 4,   // worker rank -> rank 0: still running its case (empty), every kHeartbeatInterval
};

// How long a waiting rank sleeps between two looks for a message. Open MPI's blocking receive
// busy-polls and would take a core from the rank that computes beside it; 2 ms costs a message
// at most that much latency and the waiting rank almost no CPU.
inline constexpr std::chrono::milliseconds kPollPause{2};

struct TextMessage {
  int source = 0;
  int tag = 0;
  std::string text;
};

void send_text(int destination, int tag, std::string_view text);

// A text on its way to one rank that the sender does not wait for: a rank stopped before it takes
// its message (hung, or on a node that is lost) must not hold the sender, as a blocking send would
// even for a short message. The text is kept here until the receiver has it; destroying a send
// waits for that, so a sender destroys one only when its receiver has answered or the job aborts.
class PendingSend {
 public:
  PendingSend(int destination, int tag, std::string text);
  ~PendingSend();
  PendingSend(const PendingSend&) = delete;
  PendingSend& operator=(const PendingSend&) = delete;

 private:
  const std::string text_;
  MPI_Request request_ = MPI_REQUEST_NULL;
};

// The next message from `source` with `tag` (MPI_ANY_SOURCE, MPI_ANY_TAG allowed) if one has
// arrived; never blocks.
std::optional<TextMessage> try_receive_text(int source, int tag);

}  // namespace aerobreak
