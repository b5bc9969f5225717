#pragma once
// Client-supplied paths, resolved only inside the folders the server was given. A path is
// refused when it is absolute, names `..`, holds a NUL or a backslash, or leads (through a
// symlink) to a file outside the folder: the server serves its assets and its roots, nothing
// else.
#include <filesystem>
#include <optional>
#include <string_view>

namespace ncvm::server {

// The canonical path of `relative` inside `root`, when it exists and stays inside it.
// An empty `relative` is the root itself.
std::optional<std::filesystem::path> resolveInside(const std::filesystem::path& root,
                                                   std::string_view relative);

// True when `path`, every symlink followed, is `root` or inside it (both must exist).
bool isInside(const std::filesystem::path& root, const std::filesystem::path& path);

// True when `relative` is a plain relative path (no `..`, not absolute, no NUL or `\`).
bool isPlainRelative(std::string_view relative);

}  // namespace ncvm::server
