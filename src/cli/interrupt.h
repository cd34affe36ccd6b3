// SIGINT / SIGTERM during a long run: the handler only raises a flag; the
// frame loop stops taking new frames, lets the ones in flight finish (their
// files are written whole or not at all) and exits non-zero.
#pragma once

#include <csignal>

namespace fh {

void install_interrupt_handlers();
bool interrupted();
int interrupt_signal();  // the signal received, 0 if none

}  // namespace fh
