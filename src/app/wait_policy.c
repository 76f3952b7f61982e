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
 * OMP_WAIT_POLICY=passive (the standard variable; GCC's and LLVM's runtimes
 * both read it): a waiting thread sleeps on a futex at once and yields the
 * core. Measured here (docs/performance.md, "Threads"): an empty fork and
 * join of two threads costs 5 us passive, and a step forks about 13 times,
 * so an idle machine loses next to nothing; a short spin first
 * (GOMP_SPINCOUNT=1000, 10000) was slower beside other processes and no
 * faster idle.
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
    if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
    execv("/proc/self/exe", argv);
    /* no exec (no /proc): run on, with the runtime's default waiting */
    unsetenv("OMP_WAIT_POLICY");
#else
    (void)argv;
#endif
}
