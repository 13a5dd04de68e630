#include "orchestrator/worker/mpi_text.hpp"

#include <mpi.h>

#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace aerobreak {

void send_text(int destination, int tag, std::string_view text) {
  if (text.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("MPI message of " + std::to_string(text.size()) + " bytes is too long");
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, destination, tag, MPI_COMM_WORLD);
}

PendingSend::PendingSend(int destination, int tag, std::string text) : text_(std::move(text)) {
  if (text_.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("MPI message of " + std::to_string(text_.size()) + " bytes is too long");
  MPI_Isend(text_.data(), static_cast<int>(text_.size()), MPI_CHAR, destination, tag, MPI_COMM_WORLD, &request_);
}

PendingSend::~PendingSend() { MPI_Wait(&request_, MPI_STATUS_IGNORE); }

std::optional<TextMessage> try_receive_text(int source, int tag) {
  int arrived = 0;
  MPI_Status status;
  // Open MPI progresses only inside MPI calls: a message that arrived while this rank slept is
  // often only pulled in by one probe and matched by the next. Looking twice before going back to
  // sleep saves a whole pause per message (measured: 6 ms -> 2 ms per case round trip).
  for (int look = 0; look < 2 && !arrived; ++look) MPI_Iprobe(source, tag, MPI_COMM_WORLD, &arrived, &status);
  if (!arrived) return std::nullopt;
  int length = 0;
  MPI_Get_count(&status, MPI_CHAR, &length);
  TextMessage message;
  message.source = status.MPI_SOURCE;
  message.tag = status.MPI_TAG;
  message.text.resize(static_cast<std::size_t>(length));
  MPI_Recv(message.text.data(), length, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return message;
}

}  // namespace aerobreak
