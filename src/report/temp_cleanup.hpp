#pragma once
// Temporary output files never outlive their run. A run stopped by SIGINT, SIGTERM, SIGHUP
// or SIGPIPE (standard output closed under `--trace -`)
// removes the temporaries it has open (the handler only calls unlink, which is
// async-signal-safe) and then dies of the signal as before; the temporaries of a run that
// could not clean up (SIGKILL, a power cut) are removed by the next run that writes the same
// output, once their process is gone. SIGXFSZ is ignored, so a file-size limit (ulimit -f)
// makes the write fail with EFBIG and is reported as an error instead of killing the run.
#include <string>

namespace ncvm {

// Installs the handlers; once per process (the command line calls it first thing).
// A signal the parent ignores (nohup's SIGHUP) stays ignored.
void installTempCleanup();

// Temporaries named for `target`: TARGET.ncvm-PID-RANDOM.tmp in the target's folder.
std::string tempNameFor(const std::string& target, const std::string& random);
// Removes the temporaries of `target` left by processes that no longer exist.
void removeStaleTemps(const std::string& target);

// The handlers remove registered paths: a file, or a folder of plain files (--stock-out's
// set). register returns a slot (or -1 when all are in use: the file is then still removed
// on every normal path, only not on a signal).
int registerTemp(const std::string& path, bool folder = false);
void unregisterTemp(int slot);

}  // namespace ncvm
