// SIGINT and SIGTERM for every command that runs to an end (render,
// compare, probe, normals, bench, advise, batches). The first signal is
// noted (Interruption) and the command stops at its next safe point: a
// batch between shots, with every picture it finished on disk. Work that has
// no such point soon (a mesh still being read, a picture still being
// encoded) is not waited for past GraceSeconds (an alarm): then the
// temporaries of this process are removed, the image writer follows (it dies with its parent),
// and the process exits 128 + the signal. So a run ends within
// GraceSeconds and a fraction after the signal, and leaves whole files or
// none.
#ifndef shadelab_interruption_h
#define shadelab_interruption_h

namespace shadelab
{
/** How long a signalled run may take to stop by itself. */
constexpr int GraceSeconds = 2;

/** Installs the handlers (SIGINT, SIGTERM, and SIGALRM for the grace); once, first thing. */
void CatchInterruptions();

/** The signal (SIGINT or SIGTERM) that asked the run to stop, or 0. */
int Interruption();

/** "SIGINT" or "SIGTERM". */
const char* SignalName(int signal);
}

#endif
