#pragma once
// Runs a shell command for tests that drive the aerobreak program.
#include <catch2/catch.hpp>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>

namespace aerobreak::testing {

struct CommandOutput {
  std::string text;
  int exit_code;
};

// The command's stdout, with its stderr merged in unless stdout_only, and its exit code.
inline CommandOutput run_command(const std::string& command, bool stdout_only = false) {
  const std::string redirected = command + (stdout_only ? " 2>/dev/null" : " 2>&1");
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(redirected.c_str(), "r"), pclose);
  REQUIRE(pipe);
  std::string text;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe.get())) text += buffer.data();
  const int status = pclose(pipe.release());
  return {text, WEXITSTATUS(status)};
}

}  // namespace aerobreak::testing
