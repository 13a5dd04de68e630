// SHA-256 (OpenSSL libcrypto) against the example vectors of FIPS 180-2 (appendix B: "abc", the
// 448-bit message and one million "a") and the 896-bit message of the NIST examples, for bytes
// and for a file's contents.
#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include "orchestrator/study/sha256.hpp"
#include "tests/support/scratch_directory.hpp"

using aerobreak::sha256;
using aerobreak::sha256_hex;
using aerobreak::sha256_hex_of_file;
using Catch::Matchers::Contains;

namespace {

std::filesystem::path written(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
  return file;
}

const std::string k448Bits = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
const std::string k896Bits =
    "abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmnhijklmnoijklmnopjklmnopqklmnopqrlmnopqrsmnopqrstnopqrstu";

}  // namespace

TEST_CASE("sha256 of the empty message") {
  CHECK(sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST_CASE("sha256 of \"abc\" (FIPS 180-2 B.1)") {
  CHECK(sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  const auto digest = sha256("abc");
  CHECK(digest.front() == 0xba);
  CHECK(digest.back() == 0xad);
}

TEST_CASE("sha256 of the 448-bit message (FIPS 180-2 B.2)") {
  CHECK(sha256_hex(k448Bits) == "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST_CASE("sha256 of the 896-bit message (two whole blocks before the padding)") {
  CHECK(sha256_hex(k896Bits) == "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1");
}

TEST_CASE("sha256 of one million 'a' (FIPS 180-2 B.3)") {
  CHECK(sha256_hex(std::string(1000000, 'a')) == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("sha256 around the block boundary: 55, 56, 63, 64 and 65 bytes") {
  // Digests of these lengths of "a" from coreutils sha256sum: 55 bytes is the longest message
  // whose padding fits its block, 56 the shortest that needs another.
  CHECK(sha256_hex(std::string(55, 'a')) == "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318");
  CHECK(sha256_hex(std::string(56, 'a')) == "b35439a4ac6f0948b6d6f9e3c6af0f5f590ce20f1bde7090ef7970686ec6738a");
  CHECK(sha256_hex(std::string(63, 'a')) == "7d3e74a05d7db15bce4ad9ec0658ea98e3f06eeecf16b4c6fff2da457ddc2f34");
  CHECK(sha256_hex(std::string(64, 'a')) == "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb");
  CHECK(sha256_hex(std::string(65, 'a')) == "635361c48bb9eab14198e76ea8ab7f1a41685d6ad62aa9146d301d4f17eb0ae0");
}

TEST_CASE("sha256 of a file's contents: the same digest as its bytes, over many read blocks") {
  const aerobreak::testing::ScratchDirectory directory("sha256");
  CHECK(sha256_hex_of_file(written(directory.path() / "empty", "")) ==
        "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(sha256_hex_of_file(written(directory.path() / "abc", "abc")) ==
        "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // One million bytes are read in 16 blocks of 64 KiB, the last one partial.
  CHECK(sha256_hex_of_file(written(directory.path() / "million", std::string(1000000, 'a'))) ==
        "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  // Bytes that are not text, a zero byte among them, are hashed as they are.
  const std::string binary("\x00\xff\x0d\x0a\x1a", 5);
  CHECK(sha256_hex_of_file(written(directory.path() / "binary", binary)) == sha256_hex(binary));
}

TEST_CASE("sha256 of a file that cannot be read names the file") {
  const aerobreak::testing::ScratchDirectory directory("sha256_missing");
  CHECK_THROWS_WITH(sha256_hex_of_file(directory.path() / "absent.h5"), Contains("absent.h5"));
  CHECK_THROWS_WITH(sha256_hex_of_file(directory.path()), Contains("cannot read"));
}
