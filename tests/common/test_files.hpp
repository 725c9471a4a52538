// File helpers shared by the tests: temporary folders and files, running /usr/bin/python3 (the
// meshio reader), a small hand-made mesh.
#pragma once

#include "test_support.hpp"

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace pdd::test {

/// A fresh, empty folder for one test.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = temp_path(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << p;
}

/// Writes text to temp_path(name) and returns that path.
inline std::string write_temp_file(const std::string& name, const std::string& text) {
  const auto p = temp_path(name);
  write_text(p, text);
  return p.string();
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Names of the files in dir (sorted).
inline std::vector<std::string> dir_entries(const std::filesystem::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

/// What a command printed (stdout and stderr together) and its exit status (-1: it did not exit).
struct command_result {
  int code;
  std::string output;
};

/// Runs a shell command line, stderr joined to stdout.
inline command_result run_command(const std::string& command_line) {
  const std::string cmd = command_line + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return {-1, "popen failed"};
  std::string out;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, p))
    out.append(buf, n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

/// True when /usr/bin/python3 can import the given modules.
inline bool python_has(const std::string& modules) {
  if (!std::filesystem::exists("/usr/bin/python3")) return false;
  const std::string cmd = "/usr/bin/python3 -c \"import " + modules + "\" >/dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

/// Runs /usr/bin/python3 on a script (written to dir/script.py) with arguments; returns the
/// exit status and stores stdout+stderr in `output`.
inline int run_python(const std::filesystem::path& dir, const std::string& script,
                      const std::string& args, std::string& output) {
  const auto py = dir / "script.py";
  const auto log = dir / "python.log";
  write_text(py, script);
  const std::string cmd =
      "/usr/bin/python3 '" + py.string() + "' " + args + " > '" + log.string() + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  output = read_text(log);
  return rc;
}

/// A small hand-made mesh: the square [0,2]x[0,1] as two unit squares (subdomains 0 and 1),
/// each split into 4 triangles around its centre; boundary segments with markers 1..4 and the
/// interface x = 1 with marker 7.
inline triangle_mesh small_mesh() {
  triangle_mesh m;
  // 0..5: corners and interface ends, 6, 7: centres.
  m.vertices = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}, {0.5, 0.5}, {1.5, 0.5}};
  m.vertex_markers = {1, 1, 2, 2, 3, 4, 0, 0};
  m.triangles = {{0, 1, 6}, {1, 4, 6}, {4, 5, 6}, {5, 0, 6},
                 {1, 2, 7}, {2, 3, 7}, {3, 4, 7}, {4, 1, 7}};
  m.triangle_markers = {0, 0, 0, 0, 1, 1, 1, 1};
  m.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 2}, {3, 4, 3}, {4, 5, 3}, {5, 0, 4}, {1, 4, 7}};
  return m;
}

/// A tmpfs of `size` (e.g. "1m") mounted on `dir` for the test's lifetime: a full disk. Needs
/// root; mounted() is false where it cannot be mounted (the test then skips).
class small_file_system {
public:
  small_file_system(const std::filesystem::path& dir, const char* size) : dir_(dir) {
    std::filesystem::create_directories(dir);
    mounted_ = std::system(("mount -t tmpfs -o size=" + std::string(size) + " tmpfs '" +
                            dir.string() + "' 2>/dev/null")
                               .c_str()) == 0;
  }
  ~small_file_system() {
    if (mounted_) (void)std::system(("umount '" + dir_.string() + "'").c_str());
  }
  small_file_system(const small_file_system&) = delete;
  small_file_system& operator=(const small_file_system&) = delete;
  bool mounted() const { return mounted_; }
  /// Remounts it with `size` (space freed, the files kept); true when that worked.
  bool resize(const char* size) {
    return mounted_ && std::system(("mount -o remount,size=" + std::string(size) + " '" +
                                    dir_.string() + "' 2>/dev/null")
                                       .c_str()) == 0;
  }

private:
  std::filesystem::path dir_;
  bool mounted_ = false;
};

} // namespace pdd::test
