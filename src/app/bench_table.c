/* bench_table.c - the table `lamina bench engine` prints in 2D
 * (bench_engine.c) and 3D (bench_engine3.c): its header, its rows, the
 * plain loop's row that each size starts with, the two clocks the rows
 * are timed by, and the timing of a case (bench_time_case). One copy, so
 * that the two tables keep the same columns and time their cases alike. */
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "bench.h"

static double clock_s(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double bench_wall_s(void) { return clock_s(CLOCK_MONOTONIC); }
double bench_cpu_s(void) { return clock_s(CLOCK_PROCESS_CPUTIME_ID); }

void bench_table_head(int width)
{
    printf("| %-*s | particles |   steps |       s | M p-steps/s | M p-steps/CPU-s | "
           "x plain | x plain, CPU |\n", width, "case");
    printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
}

void bench_table_row(int width, const char *name, size_t n, long steps, double secs,
                     double cpu, double done, double plain, double plain_cpu)
{
    printf("| %-*s | %9zu | %7ld | %7.3f | %7.2f | %7.2f | %5.2f | %5.2f |\n", width, name, n,
           steps, secs, done / secs / 1e6, done / cpu / 1e6, done / secs / plain,
           done / cpu / plain_cpu);
    fflush(stdout);
}

double bench_plain_row(int width, double particles, double work, double *plain_cpu)
{
    size_t np = 0;
    double plain = bench_plain_rate(particles, work, &np, plain_cpu);
    if (plain <= 0) {
        fprintf(stderr, "lamina bench engine: plain loop: out of memory\n");
        return -1;
    }
    printf("| %-*s | %9zu | %7s | %7s | %7.2f | %7.2f | %5.2f | %5.2f |\n", width, "plain loop",
           np, "", "", plain / 1e6, *plain_cpu / 1e6, 1.0, 1.0);
    return plain;
}

int bench_time_case(const bench_case *k, double work, double plain, double plain_cpu)
{
    double secs = 0, cpu = 0, done = 0;
    long steps_total = 0;
    size_t n = 0;
    while (done < work) {
        void *sim = k->build(k->ctx);
        if (!sim) {
            fprintf(stderr, "lamina bench %s: %s: could not build the case (out of memory?)\n",
                    k->cmd, k->name);
            return -1;
        }
        n = k->particles(sim);
        long steps = (long)fmin(fmax(10, (work - done) / (double)n), k->t_max / k->dt(sim));
        if (k->steps_max > 0 && steps > k->steps_max) steps = k->steps_max;
        if (steps < 1) steps = 1;
        /* as a script's sim:run steps: each step knows another follows */
        if (k->step(sim, 1) != 0) goto failed;     /* warm-up */
        double t0 = bench_wall_s(), c0 = bench_cpu_s();
        for (long s = 0; s < steps; s++)
            if (k->step(sim, s + 1 < steps) != 0) goto failed;
        secs += bench_wall_s() - t0;
        cpu += bench_cpu_s() - c0;
        done += (double)n * (double)steps * k->counted(sim);
        steps_total += steps;
        k->release(sim, k->ctx, 1);
        continue;
    failed:
        fprintf(stderr, "lamina bench %s: %s: %s\n", k->cmd, k->name, k->error(sim));
        k->release(sim, k->ctx, 0);
        return -1;
    }
    bench_table_row(k->width, k->name, n, steps_total, secs, cpu, done, plain, plain_cpu);
    return 0;
}
