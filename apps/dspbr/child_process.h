// Running another program from a command (the report scripts, glslangValidator): posix_spawnp
// with the arguments as given (no shell), the output to the terminal or a file, and the child
// registered with the interrupt handling (interrupt_cleanup.h): SIGINT or SIGTERM to dspbr stops
// the child and every process it started (its own process group) before the run's folder is
// discarded, so that nothing outlives an interrupted run (std::system ignored SIGINT in the caller
// while the child ran; the report script's workers outlived a signal sent to it alone).
#pragma once
#include <string>
#include <vector>

namespace dspbr::cli {

struct ChildExit {
  bool started = false;  // false: argv[0] could not be run (error holds errno: ENOENT when not found)
  int error = 0;
  int status = -1;       // its exit status, or 128 + the signal that ended it
};

// Runs argv (argv[0] searched on PATH); `log` "": output to the terminal, else stdout and stderr
// into the file `log` (created or truncated). `env`: NAME=VALUE entries set for the child on top
// of this process's environment.
ChildExit run_child(const std::vector<std::string>& argv, const std::string& log = "",
                    const std::vector<std::string>& env = {});

}  // namespace dspbr::cli
