/* wait_policy.c - threads that wait for each other give the core away
 * (issue 17 item 2).
 *
 * Each phase of the step is an OpenMP parallel loop; a thread that ends
 * its share first waits at the loop's barrier. GCC's libgomp makes it spin
 * there for about 300 000 rounds (milliseconds) before it sleeps. On an idle
 * machine that is the fastest wait; with one other CPU-bound process on a
 * 2-core machine the spinning thread takes the core its partner needs, and
 * `threads = 2` took 56 s where one thread took 1.8 s (31x slower).
 *
 * libgomp reads its wait policy from the environment once, when it is
 * loaded, before main: setenv inside the program is too late, and there is
 * no call to change it. So `lamina` starts itself again, once, with
 * GOMP_SPINCOUNT=3000: a waiting thread spins about 50 us (16 ns a round
 * here) and then sleeps on a futex, yielding the core. Not passive at
 * once: this 2-core VM halts an idle vCPU at once (haltpoll, poll time 0),
 * and waking a sleeping thread there cost about 0.1 ms a fork (the
 * dog-bone's 2 threads with OMP_WAIT_POLICY=passive: 9.4 s against 2.2 s
 * over some 6000 steps of about 11 forks, docs/decisions.md), and a step
 * of 1e5 particles forks 11 times; 50 us covers the short waits of an
 * idle machine (serial gaps, a phase's imbalance). 1e5 particles, 2
 * threads against 1 beside a busy loop and 5-12 other busy processes:
 * spin 0 (passive) 1.6-2.9x as fast, 1000: 1.1-2.6x, 3000: 1.0-1.8x,
 * 10 000: 0.38x, libgomp's default (300 000, 5 ms): 0.37x
 * (docs/performance.md, "Threads"). KMP_BLOCKTIME=0 does the same for
 * LLVM's runtime (passive: its spin is set in milliseconds).
 *
 * Left alone: a user's own OMP_WAIT_POLICY, GOMP_SPINCOUNT or KMP_BLOCKTIME
 * (`OMP_WAIT_POLICY=active lamina ...` gives the old behaviour), a build
 * without OpenMP, and a process with LD_PRELOAD (valgrind's tools and
 * profilers are preloaded, and would not follow the exec). */
#include <stdlib.h>
#include <unistd.h>

#include "app.h"

void app_wait_policy(char **argv)
{
#if defined(_OPENMP) && defined(__linux__)
    if (getenv("OMP_WAIT_POLICY") || getenv("GOMP_SPINCOUNT") || getenv("KMP_BLOCKTIME") ||
        getenv("LD_PRELOAD"))
        return;
    if (setenv("GOMP_SPINCOUNT", "3000", 1) != 0 || setenv("KMP_BLOCKTIME", "0", 1) != 0)
        return;
    execv("/proc/self/exe", argv);
    /* no exec (no /proc): run on, with the runtime's default waiting */
    unsetenv("GOMP_SPINCOUNT");
    unsetenv("KMP_BLOCKTIME");
#else
    (void)argv;
#endif
}
