#pragma once
// Runs the real demoplan-cli binary as a user would, capturing its exit status, stdout and
// stderr, for the CLI tests.
#include <stdlib.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace demoplan::testing_support {

namespace fs = std::filesystem;

inline std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void write_text(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) throw std::runtime_error("test setup: cannot write " + p.string());
}

inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

inline fs::path make_temp_dir(const std::string& prefix) {
  std::string tmpl = (fs::temp_directory_path() / (prefix + "XXXXXX")).string();
  if (!mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
  return tmpl;
}

struct CliResult {
  int code = -1;  // exit status; -1 when the process did not exit normally (crash)
  std::string out, err;
};

// Runs the shell command `cmd`, its output captured in files under `scratch`.
inline CliResult run_command(const std::string& cmd, const fs::path& scratch) {
  const fs::path out = scratch / "stdout", err = scratch / "stderr";
  const std::string redirected =
      cmd + " >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string()) + " </dev/null";
  const int status = std::system(redirected.c_str());
  CliResult r;
  r.code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

// Runs demoplan-cli with `args`, its output captured in files under `scratch`; `env` is
// prepended to the command ("NAME=value ").
inline CliResult run_cli(const std::vector<std::string>& args, const fs::path& scratch, const std::string& env = "") {
  std::string cmd = env + shell_quote(DEMOPLAN_CLI);
  for (const auto& a : args) cmd += " " + shell_quote(a);
  return run_command(cmd, scratch);
}

}  // namespace demoplan::testing_support
