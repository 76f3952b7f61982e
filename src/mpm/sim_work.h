/* sim_work.h - the engine's scratch state, private to it (issue 33 item 1):
 * work arrays and timings of the step that no caller reads or sets, kept
 * out of the public lm_sim behind its opaque pointer `work` (made by
 * lm_sim_new, freed by lm_sim_free). */
#ifndef LAMINA_SIM_WORK_H
#define LAMINA_SIM_WORK_H

#include <stddef.h>

struct lm_con;
struct lm_ahead;
struct lm_nwork;
struct lm_subcycle;
struct lm_apic;

typedef struct lm_work {
    double *cell_rho;      /* density.c: gas density per cell (nx * ny) */
    double *cell_stress;   /* stress_cell.c: sum V sigma per cell (3 nx ny) */
    double *pin_w, *pin_vx, *pin_vy;   /* per node: sum of the held particles'
                              N_ip and N_ip v_p (allocated with the first pin) */
    double *mass_p0;       /* damping.c: the lumped nodal momenta (x then y,
                              2 per node) before step 3's mass correction, for
                              the damping's account; made with the sim when
                              mass is not "lumped" */
    struct lm_con *cons;   /* constraint.c: the heavy end points of the step */
    size_t ncons, capcons;
    struct lm_nwork *nwork;       /* the normals' scratch (normals_work.h), made
                                     by the first step that needs it; NULL: none */
    struct lm_ahead *ahead;       /* the fused pass's nodal arrays (step_fused.c);
                                     NULL until a plain run's first step */
    struct lm_apic *apic;         /* apic.c: the points' affine velocities
                                     (lamina.sim{transfer = "apic"}); NULL: none */
    struct lm_subcycle *sub;      /* multi-rate stepping's nodal arrays
                                     (subcycle.c); NULL until its first step */
    int courant_checked;          /* the Courant check passed and nothing that
                                     moves the number changed since
                                     (courant_check.c) */
    struct {                      /* the OS threads of the loops (threads.c) */
        int team;                 /* now; 0: not yet chosen */
        int fixed;                /* > 0: held there (lm_sim_fix_team) */
        int phase;                /* timing the whole team, one thread, or holding */
        int left;                 /* steps left of the window or the hold */
        double wall0, cpu0;       /* the clocks at the window's start */
        double t_full;            /* the whole team's wall time a step */
    } pace;
} lm_work;

#endif
