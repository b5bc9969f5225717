#pragma once
// Setups in layers, as `--setup` given more than once: a preset (presets/), then the job's own
// file, later ones overriding earlier ones (docs/setup-format.md). The page's Setup tab lists
// the layers of a run; the run request carries them as
//   "setups": [{"root": R, "path": P} | {"tab": true}, ...]
// in the order they apply: R is "presets" or one of the server's folders, P a .toml file in
// it; {"tab": true} stands for the setup the run has without layers (the tab's text, else the
// program's own setup, else the --setup file) and is last when not given.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "machine/setup.hpp"

namespace ncvm::server {

struct ServerConfig;

// Turns the request's "setups" into the job's "setup_layers": [{"text", "name"}, ...] (the
// files read here, inside their folders; the tab's layer from job["setup"], which it
// replaces). Returns an error message for a layer that is not a setup file of the server.
std::optional<std::string> addSetupLayers(const nlohmann::json& request, const ServerConfig& cf,
                                          nlohmann::json& job);

// GET /api/setups: {"presets": [FILE, ...], "roots": [{"name", "files": [PATH, ...]}]}, the
// .toml files a layer may name (at most 1000 per folder, six levels deep).
nlohmann::json setupFiles(const ServerConfig& cf);

// The worker's side: defaultSetup() with each layer applied in turn as the command line applies
// a --setup file (loadSetupInto, through a private temporary copy of the text). Errors name the
// layer ("presets/fanuc-0i-mf.toml:12: ..."); files a layer names (target.polyline,
// target.height_map) stay relative, for run_job.cpp to find in the program's folder.
Setup layeredSetup(const nlohmann::json& layers);

}  // namespace ncvm::server
