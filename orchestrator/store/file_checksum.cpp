#include "orchestrator/store/file_checksum.hpp"

#include <fcntl.h>
#include <openssl/evp.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace aerobreak {
namespace {

class FileDescriptor {
 public:
  explicit FileDescriptor(const std::filesystem::path& file) : fd_(::open(file.c_str(), O_RDONLY | O_CLOEXEC)) {
    if (fd_ < 0) throw std::runtime_error("cannot open " + file.string() + ": " + std::strerror(errno));
  }
  ~FileDescriptor() { ::close(fd_); }
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

void check(int ok, const char* step) {
  if (ok != 1) throw std::runtime_error(std::string("libcrypto SHA-256: ") + step + " failed");
}

}  // namespace

std::string file_sha256_hex(const std::filesystem::path& file) {
  const FileDescriptor input(file);
  const std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  if (!context) throw std::runtime_error("libcrypto SHA-256: no context");
  check(EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr), "init");
  std::array<char, 65536> block;
  for (;;) {
    const ssize_t n = ::read(input.get(), block.data(), block.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error("cannot read " + file.string() + ": " + std::strerror(errno));
    if (n == 0) break;
    check(EVP_DigestUpdate(context.get(), block.data(), static_cast<std::size_t>(n)), "update");
  }
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  check(EVP_DigestFinal_ex(context.get(), digest.data(), &length), "final");
  static constexpr char kHex[] = "0123456789abcdef";
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) {
    hex += kHex[digest[i] >> 4];
    hex += kHex[digest[i] & 0xf];
  }
  return hex;
}

}  // namespace aerobreak
