#include "orchestrator/store/data_paths.hpp"

namespace aerobreak {

std::filesystem::path default_data_directory(const std::filesystem::path& store_file) {
  std::filesystem::path path(store_file);
  return path.replace_extension(".data");
}

std::string stored_data_path(const std::filesystem::path& data_directory, const std::string& file) {
  if (file.empty() || data_directory.empty()) return file;
  const std::filesystem::path relative =
      std::filesystem::path(file).lexically_normal().lexically_relative(data_directory.lexically_normal());
  if (relative.empty() || relative.is_absolute() || *relative.begin() == "..") return file;
  return relative.string();
}

std::string data_path_on_disk(const std::filesystem::path& data_directory, const std::string& stored) {
  const std::filesystem::path path(stored);
  if (stored.empty() || path.is_absolute() || data_directory.empty()) return stored;
  return (data_directory / path).string();
}

}  // namespace aerobreak
