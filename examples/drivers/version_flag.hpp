/// \file version_flag.hpp
/// `--version` for every pdd-* program: prints "<program> <version>" (pdd::version, from
/// CMakeLists.txt's project(VERSION)) to stdout and exits 0, before any other check (a required
/// input, Triangle's switches). help2man reads it for the man pages (cmake/PddManPages.cmake).
#pragma once

#include <pdd/version.hpp>

#include <CLI/CLI.hpp>

#include <string>
#include <string_view>

namespace pdd::drivers {

inline void add_version_flag(CLI::App& app, std::string_view program) {
  app.set_version_flag("--version", std::string(program) + " " + std::string(pdd::version),
                       "print the program's name and version and exit");
}

} // namespace pdd::drivers
