#pragma once
// Temporaries removed when the process is ended by SIGTERM, SIGINT or
// SIGHUP: a run interrupted by Ctrl-C or `kill` must not leave its hidden
// `.NAME.tmp-PID-XXXXXX` folder (513 MB in one case) beside --out. The
// process then dies of the same signal (default action), so that its exit
// status still says which signal ended it.
//
// How: the first registration installs a handler for the three signals
// (not for one the process inherited as ignored: `nohup`, background jobs
// started by a non-interactive shell). Paths are kept in a fixed table of
// static buffers; the handler removes each registered tree with raw system
// calls only (openat, getdents64, unlinkat: async-signal-safe, no
// allocation), restores the default action and re-raises the signal.
// The handler runs on the interrupted thread, so when that is the thread
// writing the folder, nothing is written into it while it is removed.
//
// SIGKILL cannot be caught: its leftovers are removed by the next
// OutputDirectory::open of the same target (output_directory.h).
//
// Child programs run in their own process group (a LIGGGHTS run: so that a
// wall-clock limit kills all it started) are out of reach of a Ctrl-C at
// the terminal; the handler sends each registered group SIGTERM first.

#include <sys/types.h>

#include <filesystem>

namespace repose {

// Registers `path` (a folder or file this process created; made absolute)
// for removal on those signals. Returns a slot for forget_on_interrupt, or
// -1 when the table is full (the path is then left to the next run's sweep).
int remove_on_interrupt(const std::filesystem::path& path);
// Unregisters a slot (after commit or after removing the path normally).
// A slot of -1 is ignored.
void forget_on_interrupt(int slot);

// Registers a child's process group to be sent SIGTERM on those signals.
// Returns a slot for forget_group_on_interrupt, or -1 when the table is full.
int end_group_on_interrupt(pid_t process_group);
// Unregisters it (once the child has been waited for). -1 is ignored.
void forget_group_on_interrupt(int slot);

}  // namespace repose
