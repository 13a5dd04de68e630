#include "orchestrator/study/sha256.hpp"

#include <fcntl.h>
#include <openssl/evp.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

namespace aerobreak {
namespace {

// A running SHA-256 computation: an EVP digest context, freed with the object.
class Sha256Context {
 public:
  Sha256Context() : context_(EVP_MD_CTX_new(), EVP_MD_CTX_free) {
    if (!context_ || EVP_DigestInit_ex(context_.get(), EVP_sha256(), nullptr) != 1)
      throw std::runtime_error("SHA-256: libcrypto could not start a digest");
  }

  void add(const void* bytes, std::size_t size) {
    if (EVP_DigestUpdate(context_.get(), bytes, size) != 1) throw std::runtime_error("SHA-256: libcrypto failed");
  }

  Sha256Digest finish() {
    Sha256Digest digest{};
    unsigned int size = 0;
    if (EVP_DigestFinal_ex(context_.get(), digest.data(), &size) != 1 || size != digest.size())
      throw std::runtime_error("SHA-256: libcrypto failed");
    return digest;
  }

 private:
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context_;
};

// A file open for reading, closed with the object.
struct ReadOnlyFile {
  explicit ReadOnlyFile(const std::filesystem::path& file) : descriptor(::open(file.c_str(), O_RDONLY | O_CLOEXEC)) {
    if (descriptor < 0)
      throw std::runtime_error("cannot open " + file.string() + " to compute its SHA-256: " + std::strerror(errno));
  }
  ReadOnlyFile(const ReadOnlyFile&) = delete;
  ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;
  ~ReadOnlyFile() { ::close(descriptor); }
  const int descriptor;
};

}  // namespace

Sha256Digest sha256(std::string_view bytes) {
  Sha256Context context;
  context.add(bytes.data(), bytes.size());
  return context.finish();
}

std::string sha256_hex(std::string_view bytes) { return to_hex(sha256(bytes)); }

Sha256Digest sha256_of_file(const std::filesystem::path& file) {
  // POSIX reads rather than a stream: a read error (a directory, an I/O fault) must be an error,
  // not the digest of the bytes read before it.
  const ReadOnlyFile in(file);
  Sha256Context context;
  std::vector<char> block(1 << 16);
  for (;;) {
    const ssize_t count = ::read(in.descriptor, block.data(), block.size());
    if (count == 0) break;
    if (count < 0 && errno == EINTR) continue;
    if (count < 0)
      throw std::runtime_error("cannot read " + file.string() + " to compute its SHA-256: " + std::strerror(errno));
    context.add(block.data(), static_cast<std::size_t>(count));
  }
  return context.finish();
}

std::string sha256_hex_of_file(const std::filesystem::path& file) { return to_hex(sha256_of_file(file)); }

std::string to_hex(const Sha256Digest& digest) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string text;
  text.reserve(2 * digest.size());
  for (const std::uint8_t byte : digest) {
    text += kDigits[byte >> 4];
    text += kDigits[byte & 0x0f];
  }
  return text;
}

}  // namespace aerobreak
