#pragma once
// What ncvm and ncvm-serve do alike with their command line and with an error that ends a
// command (docs: exit status 0 normal end, 2 usage or setup error).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>

#include "machine/setup.hpp"

namespace ncvm {

// Parses the command line: nothing to go on, else the exit status (0 after --help or
// --version, 2 for a usage error, which CLI11 has printed).
inline std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  return std::nullopt;
}

// Prints the error that ended a command and returns its exit status (2).
inline int commandError(const std::exception& e) {
  if (const auto* s = dynamic_cast<const SetupError*>(&e))
    fmt::print(stderr, "ncvm: setup error: {}\n", setupErrorText(*s));
  else if (const auto* f = dynamic_cast<const std::filesystem::filesystem_error*>(&e))
    fmt::print(stderr, "ncvm: {}: {}\n", f->path1().string(), f->code().message());
  else
    fmt::print(stderr, "ncvm: {}\n", e.what());
  return 2;
}

}  // namespace ncvm
