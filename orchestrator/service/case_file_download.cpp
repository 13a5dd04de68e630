#include "orchestrator/service/case_file_download.hpp"

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "orchestrator/service/http_support.hpp"

namespace aerobreak {
namespace {

constexpr std::size_t kChunkBytes = 1 << 16;

bool lies_under(const std::filesystem::path& file, const std::filesystem::path& directory) {
  const auto relative = file.lexically_relative(directory);
  return !relative.empty() && *relative.begin() != ".." && relative.is_relative();
}

// The store's file for the case, checked; RequestError 404 naming what is missing.
std::filesystem::path case_file(Store& store, std::int64_t case_id, const std::filesystem::path& data_directory,
                                DataFileChecker& checker) {
  const std::string which = "case " + std::to_string(case_id);
  if (data_directory.empty()) throw RequestError{404, "this service serves no case files"};
  const auto detail = store.case_detail(case_id);
  if (!detail) throw RequestError{404, "no " + which};
  if (!detail->data_file) throw RequestError{404, which + " has no HDF5 file (it has no result)"};
  std::error_code error;
  const auto file = std::filesystem::weakly_canonical(*detail->data_file, error);
  const auto directory = std::filesystem::weakly_canonical(data_directory, error);
  if (error || !lies_under(file, directory) || !std::filesystem::is_regular_file(file))
    throw RequestError{404, which + "'s HDF5 file is not in the service's data folder (moved or deleted?)"};
  // Not the file its worker wrote: refused rather than served as if it were.
  if (const auto check = checker.check(*detail->data_file, detail->data_file_digest);
      check.state == DataFileState::damaged)
    throw RequestError{
        409, which + "'s HDF5 file is damaged (" + check.problem + "): submit its study again to compute it again"};
  return file;
}

}  // namespace

void send_case_file(httplib::Response& response, Store& store, std::int64_t case_id,
                    const std::filesystem::path& data_directory, DataFileChecker& checker) {
  const auto file = case_file(store, case_id, data_directory, checker);
  auto in = std::make_shared<std::ifstream>(file, std::ios::binary);
  if (!*in) throw RequestError{404, "case " + std::to_string(case_id) + "'s HDF5 file cannot be read"};
  const auto size = static_cast<std::size_t>(std::filesystem::file_size(file));
  response.set_header("Content-Disposition", "attachment; filename=\"case-" + std::to_string(case_id) + ".h5\"");
  response.set_content_provider(size, "application/x-hdf5",
                                [in](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                                  std::vector<char> buffer(std::min(length, kChunkBytes));
                                  in->seekg(static_cast<std::streamoff>(offset));
                                  in->read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
                                  const auto got = static_cast<std::size_t>(in->gcount());
                                  if (got == 0) return false;
                                  sink.write(buffer.data(), got);
                                  return true;
                                });
}

}  // namespace aerobreak
