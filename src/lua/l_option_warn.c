/* l_option_warn.c - a run on an option that the verification suite finds
 * wrong for its kind of scene says so, once a script (issue 30 item 2: "an
 * option that fails a case is said so in the table and, when a script uses
 * it for that kind of scene, the run warns once naming the case").
 *
 * The cases and their numbers are docs/verification.md's (tests/verify/):
 *
 *  - the bilinear basis with a gas: a gas point pushes the grid with
 *    V p grad N = (gamma - 1) m e grad N, and the bilinear grad N is
 *    constant inside a cell, so while the points stay in their cells only
 *    the energy's share (gamma - 1) p of the stiffness gamma p acts: the
 *    sound speed is sqrt((gamma - 1) p / rho) (gas_acoustic: period +88 %
 *    at 10, 20 and 40 cells). Shocks that carry points across cells (Sod,
 *    the papers' runs) are not hit.
 *  - point forces on a membrane ([M]'s quadrature, one point's stress on
 *    its own stencil): the strings' periods miss by 3-50 %, their energy
 *    is not kept, and the chain, the balloon and circles at 0.4-0.8 cells
 *    tear on the bilinear basis (string_wall_*, string_pin_*, catenary,
 *    balloon_drop, circle_spacing*); the segment form passes them.
 *  - sim:contact friction under scheme = "musl" (the default): the block on
 *    the incline is held back harder than Coulomb allows as the cell
 *    shrinks, acceleration -0.32 / -13.6 / -11.9 % at cells 0.1 / 0.05 /
 *    0.025 on uGIMP (linear -5.8 / -10.9 %); under "usl" -0.07 / -2.44 /
 *    -0.16 % (incline; docs/robustness.md "Verification cases on the
 *    default"). Friction is refused on the default basis, so every
 *    friction scene is on gimp or linear; the warning names the scheme.
 *  - a membrane with segment forces on an explicit mass = "lumped" (the
 *    default, "auto", gives such a sim "membrane", l_sim.c): the
 *    lumped mass's dispersion rings a taut string's higher modes too
 *    slowly, periods of modes 2 / 3 +4.3 / +10.1 % at cell 1/16 (the
 *    string 16 cells long), +1.04 / +2.35 % at 1/32, second order
 *    (string_wall_mode2/3; pinned: +3.84 / +9.36, +0.88 / +2.21 %).
 *    Why (docs/robustness.md "Where the string's dispersion comes from"):
 *    a segment point's force reaches it through N^T M_L^-1 N and it moves
 *    with the re-mapped velocity, N^T M_L^-1 N M_p v: two lumped-mass
 *    smoothings, each sinc^6(theta/2) in the Bloch analysis, so omega_h /
 *    omega = 1 - 25 theta^2 / 96 with points h/2 apart (predicted +4.10 /
 *    +9.49 % at cell 1/16, +1.01 / +2.29 % at 1/32), whatever the points
 *    a cell (+9.1 % for mode 3 at 8 a cell). mass = "membrane" (the
 *    consistent-mass correction on the membranes' points only) and
 *    "corrected" pass them (+0.34 / +1.12, +0.05 / +0.14 %) and every
 *    other membrane case; "membrane" is the default's choice and costs 1.18 x
 *    a step on a gas-filled circle and 1.48 x on the trampoline (a sheet
 *    and a small ball), "corrected" about 2 x and a Courant factor of
 *    0.63 (the default changed every gallery page with a segment membrane;
 *    docs/robustness.md "The membranes' consistent mass").
 *  - (transfer = "apic" with a gas inside a membrane was warned of while
 *    the membrane's FLIP and the gas's APIC did not conserve momentum
 *    together, src/mpm/apic.c: the gas-filled circle at 0.4 cells' spacing
 *    missed its hoop stress by 37.6 %, the sphere at 0.2 cells by 27.6 %;
 *    with the membranes' remainder taken against their own nodal field
 *    they pass, 0.02 and 0.02 / 0.11 %, and the rest of the suite misses
 *    on it only what it misses on FLIP.)
 *  - a solid that spins on transfer = "flip" (the default): FLIP's
 *    transfers lose its angular momentum into ringing strain energy, and
 *    the spinning disk (8 and 16 cells across) keeps 85.4 / 97.4 % of it by
 *    half a turn and misses the centrifugal stress the virial asks for by
 *    13.7 / 2.6 %; transfer = "apic" keeps it and passes (+0.06 /
 *    -0.10 %). "Spins": the rigid rotation about the body's mass centre
 *    that best fits its points' velocities (omega = L / I about the mass
 *    centre) carries at least half of its kinetic energy, checked at each
 *    sim:run until said (a body set spinning later is caught then).
 *    Solids only: the suite has no rotating gas.
 *  - a gas with the artificial viscosity (av, [F] eq 24): its switch, D =
 *    div v < 0 at the point ([F] eq 25), fires in a plateau behind a
 *    rarefaction too, where the exact flow has D = 0: on the wave train the
 *    fan's tail leaves and on the grid-scale velocity fluctuations of gas
 *    crossing the cells (not FLIP's: pic = 0.01 leaves them). There its
 *    mean q is the missing pressure: at the contact the grid balances the
 *    right gas's p against the left's p + q. Sod's left plateau (sod30,
 *    docs/robustness.md "Sod's stall"): -4.38 / -2.15 % at cells 0.01 /
 *    0.005 and, with [F]'s {3, 1} points a cell, -0.9 % at 100 cells
 *    across the plateau, where half its points carry q (mean +0.53 % of
 *    p*) and the continuity density has drifted +0.30 % in volume from the
 *    points' spacing (which the dynamics do not feel: V p = (gamma - 1) m
 *    e); the two sum to the miss within 0.09 %. With 6 points a cell
 *    along the flow both go (-0.20 %). av off on the expanding gas takes q
 *    away (-2.12 / -0.82 % at cells 0.01 / 0.005) but lets the plateau
 *    ring (velocity rms 9.6 / 6.2 % of u*, against 2.7 / 1.5 % with av),
 *    so the warning does not offer it.
 *  - (mass = "corrected" with pins was warned of until the correction took
 *    the pins' constraint inside its Neumann step, mass_corrected.c: the
 *    pinned strings and the pinned membrane at rest pass with it now.)
 *
 * On the default's basis (quadratic B-spline) no other option misses more
 * than the default does in the matrix: "usl" misses the same cases by the
 * same amounts, so it gets no warning.
 *
 * The papers' scripts name these options on purpose (their figures are the
 * papers' scheme) and get the warning too: it says what the numbers are.
 * Once a process (a script, or a repl session), whatever sims it makes: a
 * page that runs four cells says it once, not four times. */
#include <stdio.h>

#include "mpm_contact.h"
#include "l_internal.h"
#include "l_sim3.h"

/* The first solid body (not a membrane, not a gas) whose rigid rotation
 * about its mass centre carries at least half its kinetic energy (the
 * header; a spinning body's translation counts against it), or -1; *share
 * gets that fraction. */
static int spinning_solid(const lm_sim *sim, double *share)
{
    const lm_particles *p = &sim->p;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        int kind = sim->mats[bd->mat]->kind;
        if (bd->membrane || kind == LM_GAS || bd->count < 2) continue;
        double m = 0, mx = 0, my = 0, px = 0, py = 0;
        for (size_t q = bd->first; q < bd->first + bd->count; q++) {
            m += p->m[q];
            mx += p->m[q] * p->x[q];
            my += p->m[q] * p->y[q];
            px += p->m[q] * p->vx[q];
            py += p->m[q] * p->vy[q];
        }
        if (!(m > 0)) continue;
        double cx = mx / m, cy = my / m, ux = px / m, uy = py / m;
        double L = 0, I = 0, ke = 0;
        for (size_t q = bd->first; q < bd->first + bd->count; q++) {
            double rx = p->x[q] - cx, ry = p->y[q] - cy;
            double vx = p->vx[q] - ux, vy = p->vy[q] - uy;
            L += p->m[q] * (rx * vy - ry * vx);
            I += p->m[q] * (rx * rx + ry * ry);
            ke += 0.5 * p->m[q] * (p->vx[q] * p->vx[q] + p->vy[q] * p->vy[q]);
        }
        if (!(ke > 0) || !(I > 0)) continue;
        double rot = 0.5 * L * L / I;   /* 1/2 I omega^2 */
        if (rot >= 0.5 * ke) {
            *share = rot / ke;
            return b;
        }
    }
    return -1;
}

/* Says "lamina: warning: <body> <text>" once a process (*said counts). */
static void say_once(const lm_sim *sim, int body, int *said, const char *text)
{
    char who[96];
    if (body < 0 || (*said)++) return;
    fprintf(stderr, "lamina: warning: %s %s\n", lm_body_label(sim, body, who, sizeof who), text);
}

/* One warning a process for a gas with av, 2D or 3D (the 3D gas is the 2D
 * one's scheme, [F] eqs 21-25, so it stalls the same way). */
static int said_av;
static const char av_text[] =
             "has av (the artificial viscosity, [F] eq 24): its switch, div v < 0 at the "
             "point, fires behind a rarefaction too, on the fan's wake and on the velocity "
             "fluctuations of gas crossing the cells, and the plateau's pressure sits low by "
             "the mean q there: the verification suite's Sod left plateau misses by -4.38 / "
             "-2.15 % at cells 0.01 / 0.005 and stalls at -0.9 % with 3 points a cell along "
             "the flow (docs/verification.md, case sod; half its points carry q, +0.53 % of "
             "p); 5 or more points a cell along the flow take the stall to -0.2 %, and a "
             "plateau needs about 30 cells across for 2 %, 60 for 1 %";

void la_option_warn(const la_sim *s)
{
    static int said_gas, said_point, said_friction, said_lumped, said_spin;
    const lm_sim *sim = s->sim;
    int gas = -1, point = -1, lumped = -1, av = -1;
    for (int b = 0; b < sim->nbodies; b++) {
        const lm_body *bd = &sim->bodies[b];
        int kind = sim->mats[bd->mat]->kind;
        if (kind == LM_GAS && gas < 0) gas = b;
        if (kind == LM_GAS && sim->mats[bd->mat]->av && bd->count > 0 && av < 0) av = b;
        if (bd->membrane && bd->force == LM_MFORCE_POINT && point < 0) point = b;
        if (bd->membrane && bd->force == LM_MFORCE_SEGMENT && lumped < 0) lumped = b;
    }
    say_once(sim, sim->def.basis == LM_BASIS_LINEAR ? gas : -1, &said_gas,
             "on basis = \"linear\": while its points stay in their "
             "cells the bilinear basis gives the gas a sound speed of sqrt((gamma - 1) p / rho), "
             "not sqrt(gamma p / rho) (docs/verification.md, case gas_acoustic: period +88 %); "
             "basis = \"bspline2\" (the default) or \"gimp\" do not");
    say_once(sim, point, &said_point,
             "has force = \"point\": with point forces the verification "
             "suite's strings miss their periods by 3-50 % and do not keep their energy, and "
             "on the bilinear basis its chain, balloon and circles tear (docs/verification.md, "
             "cases string_wall_*, string_pin_*, catenary, balloon_drop); force = \"segment\" "
             "(the default) passes them");
    say_once(sim, sim->def.scheme == LM_MUSL ? lm_sim_contact_friction_body(sim) : -1, &said_friction,
             "slides with law = \"friction\" under scheme = \"musl\" "
             "(the default): the verification suite's block on an incline is held back harder "
             "than Coulomb allows as the cell shrinks, acceleration -0.32 / -13.6 / -11.9 % at "
             "cells 0.1 / 0.05 / 0.025 on basis = \"gimp\" (docs/verification.md, case "
             "incline); scheme = \"usl\" gives -0.07 / -2.44 / -0.16 %");
    /* only an explicit "lumped": the default ("auto") is "membrane" here,
     * or lumped because substeps asked for it (l_sim.c, mass_resolve) */
    say_once(sim, sim->def.mass == LM_MASS_LUMPED && !s->mass_auto ? lumped : -1, &said_lumped,
             "has the lumped mass (mass = \"lumped\"): its dispersion rings a "
             "taut string's modes 2 and 3 too slowly, periods +4.3 / +10.1 % with the string 16 "
             "cells long, +1.0 / +2.35 % at 32 (docs/verification.md, cases string_wall_mode2, "
             "string_wall_mode3, string_pin_mode2, string_pin_mode3: two lumped-mass smoothings "
             "of the quadratic B-spline, predicted +4.1 / +9.5 %); mass = \"membrane\" (the "
             "consistent mass on the membranes' points only, 1.2-1.5 x the step) gives "
             "+0.34 / +1.12 and +0.05 / +0.14 % and passes every membrane case (mass = "
             "\"auto\", the default, picks it for segment-force membranes)");
    say_once(sim, av, &said_av, av_text);
    if (!said_spin && !sim->def.apic) {
        double share = 0;
        int spin = spinning_solid(sim, &share);
        if (spin >= 0) {
            char text[640];
            snprintf(text, sizeof text,
                     "spins on transfer = \"flip\" (the default): its rotation about its mass "
                     "centre carries %.0f %% of its kinetic energy, and FLIP's transfers lose a "
                     "spinning body's angular momentum into ringing; the verification suite's "
                     "spinning disk keeps 85.4 / 97.4 %% of it by half a turn and misses its "
                     "centrifugal stress by 13.7 / 2.6 %% at 8 / 16 cells across "
                     "(docs/verification.md, case spinning_disk); transfer = \"apic\" keeps it "
                     "and passes (+0.06 / -0.10 %%)",
                     100 * share);
            say_once(sim, spin, &said_spin, text);
        }
    }
}

/* The 3D sims' share of the warnings above: the gas's artificial viscosity
 * (the only option of that list a 3D sim has today). */
void la_option_warn3(const lm3_sim *sim)
{
    int any = 0;
    for (int k = 0; k < sim->nmat; k++) any |= sim->mats[k].kind == LM3_GAS && sim->mats[k].av;
    if (said_av || !any) return;
    for (size_t q = 0; q < sim->p.n; q++) {
        const lm3_material *m = &sim->mats[sim->p.mat[q]];
        if (m->kind == LM3_GAS && m->av) {
            said_av++;
            fprintf(stderr, "lamina: warning: a 3D gas (material %d) %s\n", (int)sim->p.mat[q] + 1,
                    av_text);
            return;
        }
    }
}
