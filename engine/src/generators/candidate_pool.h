// Making a stage's candidate videos concurrently: hosted generators spend minutes per video
// waiting on a server, so several candidates are in flight at once (at most `concurrency`),
// each with its own deadline and retries (HostedSession), and a candidate that fails is only
// a warning while another one succeeds.
//
// Threads: the workers never call the caller's hooks. Their log lines and progress are queued
// and handed to the hooks from the calling thread (plugin host callbacks are only safe from
// run()'s thread, svgmotion/plugin.h), which also polls the cancel check and passes it on.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "generators/hosted_session.h"

namespace svgm {

// Makes candidate i (0..n-1) and returns its file; throws svgm::Error with one line naming the
// candidate on failure. `hooks` are this candidate's (progress is its own fraction in [0,1]).
using MakeCandidate = std::function<std::filesystem::path(int i, const HostedHooks& hooks)>;

// Runs make for every candidate, at most `concurrency` at a time. Returns the files of the
// candidates that succeeded, in index order; with more than one candidate each failure goes to
// hooks.warn (else hooks.log) as its one line. Throws svgm::Error when none succeeded: the
// failure itself for one candidate, "<who>: all N candidates failed (the first: <message>)"
// for more, and "<who>: cancelled" when the user cancelled.
std::vector<std::filesystem::path> make_candidates(const std::string& who, int n, int concurrency,
                                                   const HostedHooks& hooks,
                                                   const MakeCandidate& make);

}  // namespace svgm
