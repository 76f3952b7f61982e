/* l_sim.c - lamina.sim{...}: the simulation handle, its clock and events.
 *
 * Callbacks (sim:every, sim:at) run between steps, so a live parameter
 * change made in one is applied exactly at a step boundary. Their functions
 * and the script's materials (by engine index, field "mats": the engine
 * has its own copies) live in the sim's uservalue table. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "l_boundary.h"
#include "l_internal.h"
#include "l_sim3.h"
#include "l_sim_run_common.h"

static const char *const schemes[] = {"musl", "usl", NULL};
static const char *const masses[] = {"lumped", "corrected", "membrane", NULL};
/* what the mass key accepts: the engine's three and "auto" (the default,
 * resolved by mass_resolve) */
static const char *const mass_keys[] = {"lumped", "corrected", "membrane", "auto", NULL};
#define MASS_KEY_AUTO 3
static const char *const transfers[] = {"flip", "apic", NULL};
/* in lm_multirate order (mpm.h) */
static const char *const multirates[] = {"held", "impulse", "impulse_lumped", "half",
                                         "half_lumped", "held_consistent", "split", "hybrid",
                                         NULL};
/* in lm_basis order (mpm.h) */
static const char *const bases[] = {"linear", "gimp", "bspline2", NULL};
/* lm_stress: [T] §5.4.3 (stress_cell.c) */
static const char *const stresses[] = {"points", "cell", NULL};
static const char *const sides[] = {"left", "right", "bottom", "top", NULL};

la_sim *la_check_sim_any(lua_State *L, int idx)
{
    la_sim *s = luaL_checkudata(L, idx, LA_SIM);
    if (!s->sim && !s->s3) luaL_error(L, "the simulation has been closed");
    return s;
}

/* The 2D methods take this: a 3D sim (lamina.sim{dim = 3}, l_sim3.c) is
 * refused naming the method. */
la_sim *la_check_sim(lua_State *L, int idx)
{
    la_sim *s = la_check_sim_any(L, idx);
    if (s->s3) la_sim3_refuse(L);
    return s;
}

void la_sim_keep(lua_State *L, int sidx, int idx)
{
    sidx = lua_absindex(L, sidx);
    idx = lua_absindex(L, idx);
    lua_getiuservalue(L, sidx, 1);
    lua_pushvalue(L, idx);
    luaL_ref(L, -2);
    lua_pop(L, 1);
}

static void read_cell(lua_State *L, const char *fn, lm_sim_def *d)
{
    int t = la_getfield(L, 1, "cell");
    lua_pop(L, 1);
    if (t == LUA_TTABLE) {
        la_pair(L, 1, fn, "cell", &d->hx, &d->hy);
    } else if (t != LUA_TNIL) {
        d->hx = d->hy = la_number(L, 1, fn, "cell");
    }
}

static void read_domain(lua_State *L, const char *fn, lm_sim_def *d)
{
    if (la_getfield(L, 1, "domain") == LUA_TNIL) {
        lua_pop(L, 1);
        return;
    }
    if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 4)
        luaL_error(L, "%s: 'domain' must be {x0, y0, x1, y1}", fn);
    double v[4];
    for (int i = 0; i < 4; i++) {
        lua_rawgeti(L, -1, i + 1);
        int ok;
        v[i] = lua_tonumberx(L, -1, &ok);
        if (!ok) luaL_error(L, "%s: 'domain'[%d] must be a number", fn, i + 1);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    d->x0 = v[0]; d->y0 = v[1]; d->x1 = v[2]; d->y1 = v[3];
}

/* boundary = "fixed" (every side) or {left = ..., right = ..., bottom = ...,
 * top = ...}; sides not named keep the default, fixed. */
static void read_boundary(lua_State *L, const char *fn, lm_sim_def *d)
{
    la_read_boundary(L, fn, sides, "sides", NULL, d->bc);
}

int la_sim_new(lua_State *L)
{
    static const char *const keys[] = {"domain", "cell", "dt", "scheme", "gravity",
                                       "boundary", "courant", "pic", "seed", "threads",
                                       "basis", "stress", "axisymmetric", "mass", "damping",
                                       "substeps", "transfer", "dim", "multirate",
                                       "viscous_limit", "fast_band", NULL};
    const char *fn = "lamina.sim";
    /* dim = 3: the 3D run (l_sim3.c, docs/3d.md) */
    la_check_table(L, 1, fn);
    double dim = la_opt_number(L, 1, fn, "dim", 2);
    if (dim == 3) return la_sim3_new(L);
    if (dim != 2) luaL_error(L, "%s: dim must be 2 or 3 (got %f)", fn, dim);
    la_check_keys(L, 1, fn, keys);
    lm_sim_def d;
    lm_sim_def_default(&d);
    read_domain(L, fn, &d);
    read_cell(L, fn, &d);
    d.dt = la_number(L, 1, fn, "dt");
    d.scheme = (lm_scheme)la_option(L, fn, "scheme",
                                    la_opt_string(L, 1, fn, "scheme", "musl"), schemes);
    int mass = la_option(L, fn, "mass", la_opt_string(L, 1, fn, "mass", "auto"), mass_keys);
    d.mass = mass == MASS_KEY_AUTO ? LM_MASS_LUMPED : (lm_mass)mass;   /* auto: mass_resolve */
    d.stress = (lm_stress)la_option(L, fn, "stress",
                                    la_opt_string(L, 1, fn, "stress", "points"), stresses);
    if (la_has(L, 1, "gravity")) la_pair(L, 1, fn, "gravity", &d.gx, &d.gy);
    if (!isfinite(d.gx) || !isfinite(d.gy))   /* else blamed on dt steps later */
        luaL_error(L, "%s: 'gravity' must be two finite numbers (got {%f, %f})", fn, d.gx, d.gy);
    read_boundary(L, fn, &d);
    /* The default is the quadratic B-spline: with segment forces (the
     * membranes' default) it does best on issue 13's checks
     * (docs/robustness.md "Which default"); [T] §5.4.3's cell stress is
     * bilinear, so asking for it alone keeps the papers' basis. */
    const char *basis_default = d.stress == LM_STRESS_CELL ? "linear" : "bspline2";
    d.basis = (lm_basis)la_option(L, fn, "basis",
                                  la_opt_string(L, 1, fn, "basis", basis_default), bases);
    /* transfer = "apic" (src/mpm/apic.c): its D = h^2/4 holds for the
     * quadratic B-spline only */
    d.apic = la_option(L, fn, "transfer", la_opt_string(L, 1, fn, "transfer", "flip"), transfers);
    if (d.apic && d.basis != LM_BASIS_BSPLINE2)
        luaL_error(L, "%s: transfer = \"apic\" works with basis = \"bspline2\" only (got "
                   "basis = \"%s\")", fn, bases[d.basis]);
    /* APIC's coupling with a FLIP membrane (apic.c) takes the membranes'
     * remainder against their own nodal velocity on the lumped mass; on the
     * corrected masses it does not conserve momentum: a shearing gas in a
     * ring (physics.apic_membrane_momentum) drifts 6.3e-2 of its momentum
     * on "membrane" (2e-15 lumped) and inverts at step 32 on "corrected" */
    if (d.apic && d.mass != LM_MASS_LUMPED)
        luaL_error(L, "%s: transfer = \"apic\" works with mass = \"lumped\" only (got mass = "
                   "\"%s\": with a membrane the two do not conserve momentum together)", fn,
                   masses[d.mass]);
    /* [T] §5.4.3's cell stress is a bilinear construction (gradients at the
     * cell centre of the cell's four nodes) */
    if (d.stress == LM_STRESS_CELL && d.basis != LM_BASIS_LINEAR)
        luaL_error(L, "%s: stress = \"cell\" works with basis = \"linear\" only (got "
                   "basis = \"%s\")", fn, bases[d.basis]);
    /* axisymmetric = true: x is r, y is z, per radian (src/mpm/axisym.c) */
    int at = lua_getfield(L, 1, "axisymmetric");
    if (at != LUA_TNIL && at != LUA_TBOOLEAN)
        luaL_error(L, "%s: axisymmetric must be true or false (got %s)", fn, lua_typename(L, at));
    d.axisym = lua_toboolean(L, -1);
    lua_pop(L, 1);
    d.courant = la_opt_number(L, 1, fn, "courant", 1.0);
    d.pic = la_opt_number(L, 1, fn, "pic", 0.0);
    double seed = la_opt_number(L, 1, fn, "seed", 1);
    if (!(seed >= 0 && seed < 9007199254740992.0) || seed != floor(seed))
        luaL_error(L, "%s: seed must be a whole number >= 0 (got %f)", fn, seed);
    d.seed = (uint64_t)seed;
    if (!(d.pic >= 0 && d.pic <= 1)) luaL_error(L, "%s: pic must lie in [0, 1] (got %f)", fn, d.pic);
    /* damping = c (1/s): viscous damping of the grid velocities (damping.c) */
    d.damping = la_opt_number(L, 1, fn, "damping", 0.0);
    if (!(d.damping >= 0) || !isfinite(d.damping))
        luaL_error(L, "%s: damping must be a finite number >= 0 (1/s) (got %f)", fn, d.damping);
    /* substeps = "auto" or k: the membranes in k sub-steps of each step
     * (multi-rate stepping, src/mpm/subcycle.c) */
    int st_type = lua_getfield(L, 1, "substeps");
    if (st_type == LUA_TSTRING) {
        const char *v = lua_tostring(L, -1);
        if (strcmp(v, "auto") != 0)
            luaL_error(L, "%s: substeps must be \"auto\" or a whole number from 1 to %d (got "
                       "\"%s\")", fn, LM_SUBSTEPS_MAX, v);
        d.substeps = LM_SUBSTEPS_AUTO;
    } else if (st_type == LUA_TNUMBER) {
        double k = lua_tonumber(L, -1);
        if (!(k >= 1 && k <= LM_SUBSTEPS_MAX) || k != floor(k))
            luaL_error(L, "%s: substeps must be \"auto\" or a whole number from 1 to %d (got "
                       "%f)", fn, LM_SUBSTEPS_MAX, k);
        d.substeps = (int)k;
    } else if (st_type != LUA_TNIL) {
        luaL_error(L, "%s: substeps must be \"auto\" or a whole number from 1 to %d (got a %s)",
                   fn, LM_SUBSTEPS_MAX, lua_typename(L, st_type));
    }
    lua_pop(L, 1);
    /* multirate: the sub-steps' form (subcycle.c); it means nothing
     * without them, so asking for it alone is refused */
    d.multirate = (lm_multirate)la_option(L, fn, "multirate",
                                          la_opt_string(L, 1, fn, "multirate", "held"), multirates);
    if (la_has(L, 1, "multirate") && d.substeps == 0)
        luaL_error(L, "%s: multirate = \"%s\" needs substeps (\"auto\" or a number)", fn,
                   multirates[d.multirate]);
    /* viscous_limit = kappa: a gas point's shear viscosity at most
     * kappa rho h^2 / dt (material_gas.c, lm_gas_mu); axisym.c's gas
     * update has its own viscous stress and does not take it */
    d.visc_limit = la_opt_number(L, 1, fn, "viscous_limit", 0.0);
    if (!(d.visc_limit >= 0) || !isfinite(d.visc_limit))
        luaL_error(L, "%s: viscous_limit must be a finite number >= 0 (got %f)", fn, d.visc_limit);
    if (d.visc_limit > 0 && d.axisym)
        luaL_error(L, "%s: viscous_limit works in the plane only (got axisymmetric = true)", fn);
    /* fast_band = w: the gas points within w cells of the membranes'
     * stencils join the sub-steps (src/mpm/subcycle_gasband.c) */
    if (la_has(L, 1, "fast_band")) {
        double w = la_number(L, 1, fn, "fast_band");
        if (!(w >= 0 && w <= 8) || w != floor(w))
            luaL_error(L, "%s: fast_band must be a whole number of cells from 0 to 8 (got %f)",
                       fn, w);
        if (d.substeps == 0)
            luaL_error(L, "%s: fast_band = %d needs substeps (\"auto\" or a number)", fn, (int)w);
        d.fast_band = 1;
        d.fast_band_w = (int)w;
    }
    /* threads: the key, else lamina run --threads (the run's configuration,
     * passed in explicitly), else the user's LAMINA_THREADS, else 1; the
     * state is bit-identical for the same count (docs/decisions.md) */
    const char *env = getenv("LAMINA_THREADS");
    const lamina_run *cfg = la_run(L);
    double threads = la_opt_number(L, 1, fn, "threads",
                                   cfg && cfg->threads > 0 ? cfg->threads
                                   : env && *env           ? atof(env)
                                                           : 1);
    if (!(threads >= 1 && threads <= LM_MAX_THREADS) || threads != floor(threads))
        luaL_error(L, "%s: threads must be a whole number from 1 to %d (got %f)", fn,
                   LM_MAX_THREADS, threads);
    d.threads = (int)threads;
    /* a measurement (docs/performance.md "Accuracy"): the centred normals'
     * Cholesky fits against the QR, printed when the sim is collected */
    d.normals_compare = getenv("LAMINA_NRM_CMP") != NULL;

    la_sim *s = lua_newuserdatauv(L, sizeof *s, 1);
    memset(s, 0, sizeof *s);
    lamina_run *run = la_run(L);
    s->index = run ? ++run->nsims : 1;   /* which sim a checkpoint belongs to */
    s->mass_auto = mass == MASS_KEY_AUTO;
    luaL_setmetatable(L, LA_SIM);
    lua_newtable(L);
    lua_setiuservalue(L, -2, 1);
    char err[256];
    s->sim = lm_sim_new(&d, err, sizeof err);
    if (!s->sim) luaL_error(L, "%s: %s", fn, err);
    return 1;
}

/* Only the collector calls this (the metatable is locked, there is no
 * __close); it is idempotent anyway, and la_check_sim refuses a freed sim. */
static int sim_gc(lua_State *L)
{
    la_sim *s = luaL_checkudata(L, 1, LA_SIM);
    unsigned long n, fallbacks;
    double worst, mean;
    if (s->sim && lm_sim_normals_compare(s->sim, &n, &worst, &mean, &fallbacks) == 0)
        fprintf(stderr, "LAMINA_NRM_CMP: %lu normals, Cholesky against QR: largest angle %.3g "
                "degrees, mean %.3g; %lu fits fell back to the QR\n", n, worst, mean, fallbacks);
    lm_sim_free(s->sim);
    la_sim3_free(s->s3);
    s->s3 = NULL;
    free(s->ev);
    free(s->pinf);
    free(s->ck_file);
    free(s->leak_side);
    la_ref_free(s);
    s->leak_side = NULL;
    s->leak_nb = 0;
    s->ck_file = NULL;
    s->sim = NULL;
    s->ev = NULL;
    s->pinf = NULL;
    s->npinf = 0;
    s->nev = s->capev = 0;
    return 0;
}

/* ---- events ---------------------------------------------------------- */

void la_sim_add_event(lua_State *L, int sidx, double first, double interval, int fidx)
{
    sidx = lua_absindex(L, sidx);
    fidx = lua_absindex(L, fidx);
    la_sim *s = la_check_sim_any(L, sidx);
    luaL_checktype(L, fidx, LUA_TFUNCTION);
    if (s->nev == s->capev) {
        int cap = s->capev ? 2 * s->capev : 8;
        la_event *e = realloc(s->ev, cap * sizeof *e);
        if (!e) luaL_error(L, "out of memory");
        s->ev = e;
        s->capev = cap;
    }
    la_event *e = &s->ev[s->nev++];
    memset(e, 0, sizeof *e);
    e->interval = interval;
    e->t0 = e->next = first;
    lua_getiuservalue(L, sidx, 1);
    lua_pushvalue(L, fidx);
    e->ref = luaL_ref(L, -2);
    lua_pop(L, 1);
}

void la_sim_add_pin_function(lua_State *L, int sidx, int pin, int fidx)
{
    sidx = lua_absindex(L, sidx);
    fidx = lua_absindex(L, fidx);
    la_sim *s = la_check_sim_any(L, sidx);   /* both dimensions (l_pin3.c) */
    la_pin_fn *f = realloc(s->pinf, (size_t)(s->npinf + 1) * sizeof *f);
    if (!f) luaL_error(L, "out of memory");
    s->pinf = f;
    lua_getiuservalue(L, sidx, 1);
    lua_pushvalue(L, fidx);
    f[s->npinf].ref = luaL_ref(L, -2);
    f[s->npinf].pin = pin;
    s->npinf++;
    lua_pop(L, 1);
}

/* sim:every(interval, fn): fn(sim) now (at the next step boundary) and
 * every interval of simulated time after. */
static int sim_every(lua_State *L)
{
    return la_sim_every_from(L, la_check_sim(L, 1)->sim->t);   /* l_sim_run_common.c */
}

/* sim:at(t, fn): fn(sim) once, at the first step boundary at or after t. */
static int sim_at(lua_State *L)
{
    la_check_sim(L, 1);
    return la_sim_at_time(L);
}

double la_next_multiple(double t0, double interval, double *k, double now)
{
    /* the first multiple after now, computed, not counted up to: an
     * interval far below dt (1e-300), or a clock far ahead of t0 (a
     * restart, t = 1e300), would loop for ever; an interval shorter than
     * dt fires once per step, not in bursts */
    double kk = floor((now - t0) / interval) + 1;
    if (!(kk > *k)) kk = *k + 1;
    /* the division may round: settle on the first multiple past now,
     * as counting up did (a step or two at most) */
    for (int j = 0; j < 4 && kk - 1 > *k && t0 + (kk - 1) * interval > now; j++) kk--;
    for (int j = 0; j < 4 && !(t0 + kk * interval > now); j++) kk++;
    *k = kk;
    double next = t0 + kk * interval;
    /* rounding, or an interval so small that the count overflows (5e-324),
     * or below the clock's resolution: the next step */
    if (!(next > now) || !isfinite(next)) next = nextafter(now, HUGE_VAL);
    return next;
}

void la_check_interval(lua_State *L, const char *fn, const char *what, double interval,
                       double t)
{
    char msg[256];
    if (!(interval > 0) || !isfinite(interval)) {
        snprintf(msg, sizeof msg, "must be positive and finite (got %g)", interval);
        luaL_error(L, "%s: %s %s", fn, what, msg);
    }
    /* a schedule is kept as t0 + k interval: past 2^53 multiples the count
     * no longer resolves one, and below the clock's resolution t + interval
     * is t (issue 31) */
    if (!(t + interval > t) || fabs(t) / interval > 0x1p53) {
        snprintf(msg, sizeof msg, "= %g is too small for the run's clock at t = %g (the "
                 "clock resolves %g there)", interval, t, nextafter(fabs(t), HUGE_VAL) - fabs(t));
        luaL_error(L, "%s: %s %s", fn, what, msg);
    }
}

/* Runs every event that is due. Half a step of tolerance, so that an event
 * at t = 0.1 fires at the step that lands on 0.1 up to rounding. */
/* Returns how many callbacks ran. Either dimension (a 3D run: l_sim3_run.c). */
int la_sim_fire_due(lua_State *L, la_sim *s)
{
    double now = s->s3 ? s->s3->sim->t + 0.5 * s->s3->sim->def.dt
                       : s->sim->t + 0.5 * s->sim->def.dt;
    int fired = 0;
    for (int i = 0; i < s->nev; i++) {
        la_event *e = &s->ev[i];
        if (e->done || e->next > now) continue;
        if (e->interval > 0) {
            e->next = la_next_multiple(e->t0, e->interval, &e->k, now);
        } else {
            e->done = 1;
        }
        lua_getiuservalue(L, 1, 1);
        lua_rawgeti(L, -1, e->ref);
        lua_remove(L, -2);
        lua_pushvalue(L, 1);
        fired++;
        /* an error goes to advance()'s run guard, which keeps the records */
        lua_call(L, 1, 0);
    }
    return fired;
}

/* Will a callback run after the coming step (fire_due's test at the time
 * that step ends)? Then the step need not make the next one's sums ahead:
 * the callback may change what they are made of. */
static int due_after_step(const la_sim *s)
{
    double now = s->sim->t + 1.5 * s->sim->def.dt;
    for (int i = 0; i < s->nev; i++)
        if (!s->ev[i].done && s->ev[i].next <= now) return 1;
    return 0;
}

void la_sim_skip_due(la_sim *s)
{
    double now = s->s3 ? s->s3->sim->t + 0.5 * s->s3->sim->def.dt   /* 3D: l_sim3.h */
                       : s->sim->t + 0.5 * s->sim->def.dt;
    for (int i = 0; i < s->nev; i++) {
        la_event *e = &s->ev[i];
        if (e->done || e->next > now) continue;
        if (e->interval > 0) {   /* computed: a restart far ahead hung here */
            e->next = la_next_multiple(e->t0, e->interval, &e->k, now);
        } else {
            e->done = 1;
        }
    }
}

/* ---- stepping -------------------------------------------------------- */

/* "simulation failed: ..." (exit status 1, LAMINA_FAIL_UNSTABLE): a script
 * may catch it with pcall and then fail for another reason, which is its own
 * mistake (exit status 2), not the simulation's (l_run_guard.c). */
void la_raise_sim_failure(lua_State *L, const char *why)
{
    la_fail_raisef(L, LAMINA_FAIL_UNSTABLE, "simulation failed: %s", why);
}

/* docs/design.md: a dt whose Courant number exceeds `courant` (times the
 * basis' factor) is refused: the engine's decision and message
 * (lm_sim_check_courant, courant_check.c), reported here as a refusal. */
static void check_courant(lua_State *L, la_sim *s)
{
    if (lm_sim_check_courant(s->sim) != LM_OK)
        la_fail_raisef(L, LAMINA_FAIL_REFUSED, "%s", s->sim->err);
}

/* The engine's energy watch (energy_watch.c) over one sim:run: its
 * warning said once a sim. */
static void energy_report(lua_State *L, la_sim *s, const lm_energy_watch *w)
{
    char msg[1200], line[1300];
    if (s->warned_energy || !lm_energy_watch_end(s->sim, w, msg, sizeof msg)) return;
    s->warned_energy = 1;
    snprintf(line, sizeof line, "lamina: warning: %s\n", msg);
    la_warn(L, line);
}

/* The steps left to t_end at the current dt: a dt changed by a callback
 * applies at once, so the run still ends on t_end instead of overshooting. */
/* The most steps one sim:run may take (checked at the call and again when
 * a callback changes dt). */
#define STEP_CAP LA_STEP_CAP

static long steps_to(const la_sim *s, double t_end)
{
    double n = floor((t_end - s->sim->t) / s->sim->def.dt + 0.5);
    return n > 0 ? (long)fmin(n, STEP_CAP) : 0;
}

/* What advance() hands its protected steps. */
/* mass = "auto" (the default, issue 30): "membrane" (the consistent mass on
 * the membranes' points, src/mpm/mass_corrected.c) when a membrane has
 * segment forces, else "lumped". The lumped mass's dispersion rings a taut
 * string's modes 2 / 3 +4.3 / +10.1 % slow at cell 1/16 and "membrane"
 * passes every membrane case of the verification suite (docs/robustness.md
 * "The membranes' consistent mass"); sims whose membranes all have point
 * forces (the papers' scheme) and sims without membranes keep the lumped
 * step bit for bit, and so do sims that ask for substeps (multi-rate
 * stepping is lumped only, src/mpm/subcycle.c) and sims on transfer =
 * "apic": the membrane's FLIP remainder against its own nodal velocity
 * (src/mpm/apic.c) is a lumped construction, and with "membrane" the gas
 * in a ring of tests/physics/apic_membrane_momentum.lua drifts by 6.3e-2
 * of its momentum (lumped: 2e-15). Resolved as each run starts (bodies may
 * be added between runs) and when sim.mass is read. */
static void mass_resolve(lua_State *L, la_sim *s)
{
    if (!s->mass_auto) return;
    lm_sim *m = s->sim;
    lm_mass to = LM_MASS_LUMPED;
    for (int b = 0; b < m->nbodies && m->def.substeps == 0 && !m->def.apic; b++)
        if (m->bodies[b].membrane && m->bodies[b].force == LM_MFORCE_SEGMENT) to = LM_MASS_MEMBRANE;
    if (to != m->def.mass && lm_sim_set_mass(m, to) != LM_OK) luaL_error(L, "%s", m->err);
}

/* The steps of one run, called protected by advance() with the sim at
 * index 1: any error raised here - the Courant refusal, a callback's, a pin
 * velocity function's, a failed checkpoint, a failed step, a signal - ends
 * in advance()'s run guard. */
static int run_steps(lua_State *L)
{
    la_run_arg *a = la_run_arg_take(L);
    la_sim *s = a->guard->s;
    long nsteps = a->nsteps;
    double t_end = a->t_end;
    lamina_run *run = la_run(L);
    mass_resolve(L, s);
    check_courant(L, s);
    la_progress_begin(L, 1, nsteps);
    a->guard->progress = 1;
    la_sim_fire_due(L, s);
    la_checkpoint_due(L, 1, s);
    lm_energy_watch watch;
    lm_energy_watch_begin(s->sim, &watch);
    la_leak_watch(L, s);   /* the sides are judged before the first step */
    la_option_warn(s);
    /* the script may have changed anything since the last step */
    lm_sim_forget_ahead(s->sim);
    la_ref_capture(L, s);   /* bodies added since: their reference positions */
    double dt_was = s->sim->def.dt;
    for (long n = 0; isnan(t_end) ? n < nsteps : steps_to(s, t_end) > 0; n++) {
        la_pins_update(L, 1, s);
        lm_energy_watch_step(s->sim, &watch);
        /* another step follows at once unless this is the last or a
         * callback runs in between (and one that does makes the engine
         * forget, below) */
        int more = (isnan(t_end) ? n + 1 < nsteps : steps_to(s, t_end) > 1) &&
                   !due_after_step(s);
        lm_status st = lm_sim_step_then(s->sim, more);
        if (st == LM_ERR_COURANT)   /* a live change moved the Courant number past it */
            la_fail_raisef(L, LAMINA_FAIL_REFUSED, "%s", s->sim->err);
        if (st != LM_OK) la_raise_sim_failure(L, s->sim->err);   /* the history is kept */
        if (la_sim_fire_due(L, s)) lm_sim_forget_ahead(s->sim);   /* it may have changed the state */
        la_leak_watch(L, s);
        if (!isnan(t_end) && s->sim->def.dt != dt_was) {
            /* a callback changed dt: the cap sim:run applied at its start
             * applies again (s.dt = 1e-300 ran ~for ever, issue 31) */
            dt_was = s->sim->def.dt;
            double left = floor((t_end - s->sim->t) / dt_was + 0.5);
            if (left > STEP_CAP) {
                char msg[256];
                snprintf(msg, sizeof msg, "dt = %g, set at t = %g, leaves %g steps to t_end = "
                         "%g (at most %g)", dt_was, s->sim->t, left, t_end, STEP_CAP);
                la_fail_raisef(L, LAMINA_FAIL_REFUSED, "sim:run: %s", msg);
            }
        }
        la_checkpoint_due(L, 1, s);
        /* lamina serve: its page sees the step, may pause here or change a
         * live setting (then the engine forgets what it computed ahead) */
        if (run->observer && run->observer->step &&
            run->observer->step(run->observer->ud, L, 1, s->sim))
            lm_sim_forget_ahead(s->sim);
        if (la_progress_tick(L, s->sim))   /* Ctrl-C, watch: stop between steps */
            la_interrupt_raise(L, s->sim);
    }
    energy_report(L, s, &watch);
    return 0;
}

/* nsteps steps (sim:step), or up to t_end when it is a number (sim:run),
 * the sim at index 1. Every way out goes through the run guard
 * (l_run_guard.c): the sim is not left running, the records are written. */
static void advance(lua_State *L, la_sim *s, long nsteps, double t_end)
{
    la_run_arg a = {NULL, nsteps, t_end};
    la_sim_run_protected(L, s, run_steps, &a);   /* l_sim_run_common.c */
}

void la_sim_advance(lua_State *L, la_sim *s, long nsteps)
{
    advance(L, s, nsteps, NAN);
}

/* After a run: a segment membrane with a quarter of its points slack by
 * more than 1 % beside taut ones has bunched points that carry nothing
 * (lm_membrane_segment_slack): said once per membrane, not an error (a
 * membrane may be partly slack by design). */
static void warn_bunched(lua_State *L, la_sim *s)
{
    const lm_sim *sim = s->sim;
    for (int b = 0; b < sim->nbodies && b < (int)(8 * sizeof s->warned_bunched); b++) {
        size_t taut, slack = lm_membrane_segment_slack(sim, b, &taut);
        size_t n = sim->bodies[b].count;
        if (s->warned_bunched >> b & 1 || n < 10 || taut == 0 || 4 * slack < n) continue;
        s->warned_bunched |= 1ull << b;
        char who[96], line[640];
        snprintf(line, sizeof line,
                 "lamina: warning: at t = %.6g (step %ld): %zu of the %zu points of %s are slack "
                 "by more than 1 %% while %zu carry tension: with force = \"segment\" points closer "
                 "than the grid resolves stay bunched and carry nothing (docs/robustness.md, \"The "
                 "dog-bone with segment forces\"); if it should be taut, space its points about 0.4 "
                 "cells apart at their natural length, or use force = \"point\"\n",
                 sim->t, sim->step, slack, n, lm_body_label(sim, b, who, sizeof who), taut);
        la_warn(L, line);
    }
}

void la_warn(lua_State *L, const char *line)
{
    lamina_progress_clear_line();
    fputs(line, stderr);
    lamina_run *run = la_run(L);
    if (run && run->log) {
        fputs(line, run->log);
        fflush(run->log);
    }
}

static int sim_run(lua_State *L)
{
    la_sim *s = la_check_sim(L, 1);
    double t_end;
    long n = la_sim_run_steps(L, s, &t_end);
    advance(L, s, n, t_end);
    warn_bunched(L, s);
    return 0;
}

static int sim_step(lua_State *L)
{
    la_sim *s = la_check_sim(L, 1);
    advance(L, s, la_sim_step_count(L, s), NAN);
    warn_bunched(L, s);
    return 0;
}

/* ---- diagnostics ----------------------------------------------------- */

void la_push_energy(lua_State *L, lm_energy e)
{
    lua_createtable(L, 0, 5);
    lua_pushnumber(L, e.kinetic); lua_setfield(L, -2, "kinetic");
    lua_pushnumber(L, e.strain); lua_setfield(L, -2, "strain");
    lua_pushnumber(L, e.internal); lua_setfield(L, -2, "internal");
    lua_pushnumber(L, e.potential); lua_setfield(L, -2, "potential");
    lua_pushnumber(L, e.total); lua_setfield(L, -2, "total");
}

static int sim_energy(lua_State *L)
{
    la_sim *s = la_check_sim(L, 1);
    la_push_energy(L, lm_sim_energy(s->sim));
    lua_pushnumber(L, lm_sim_grid_kinetic(s->sim));
    lua_setfield(L, -2, "grid_kinetic");
    lua_pushnumber(L, s->sim->damped);   /* the grid damping's work (damping.c) */
    lua_setfield(L, -2, "damped");
    return 1;
}

static int sim_momentum(lua_State *L)
{
    la_sim *s = la_check_sim(L, 1);
    double px, py;
    lm_sim_momentum(s->sim, &px, &py);
    lua_pushnumber(L, px);
    lua_pushnumber(L, py);
    return 2;
}

static int sim_hash(lua_State *L)
{
    la_sim *s = la_check_sim(L, 1);
    char buf[17];
    snprintf(buf, sizeof buf, "%016llx", (unsigned long long)lm_sim_hash(s->sim));
    lua_pushstring(L, buf);
    return 1;
}

static int sim_courant(lua_State *L)
{
    la_sim *s = la_check_sim(L, 1);
    double c;
    lua_pushnumber(L, lm_sim_courant(s->sim, &c));
    lua_pushnumber(L, c);
    return 2;
}

static int sim_index(lua_State *L)
{
    if (la_check_sim_any(L, 1)->s3) return la_sim3_index(L);
    la_sim *s = la_check_sim(L, 1);
    const char *k = luaL_checkstring(L, 2);
    if (strcmp(k, "mass") == 0) mass_resolve(L, s);   /* what the next step uses */
    const lm_sim *m = s->sim;
    if (strcmp(k, "t") == 0) lua_pushnumber(L, m->t);
    else if (strcmp(k, "dim") == 0) lua_pushinteger(L, 2);
    else if (strcmp(k, "nstep") == 0) lua_pushinteger(L, m->step);
    else if (strcmp(k, "dt") == 0) lua_pushnumber(L, m->def.dt);
    else if (strcmp(k, "cell") == 0) lua_pushnumber(L, m->grid.hx);
    else if (strcmp(k, "n") == 0) lua_pushinteger(L, (lua_Integer)m->p.n);
    else if (strcmp(k, "scheme") == 0) lua_pushstring(L, schemes[m->def.scheme]);
    else if (strcmp(k, "basis") == 0) lua_pushstring(L, lm_basis_name(m->def.basis));
    else if (strcmp(k, "pic") == 0) lua_pushnumber(L, m->def.pic);
    else if (strcmp(k, "mass") == 0) lua_pushstring(L, masses[m->def.mass]);
    else if (strcmp(k, "transfer") == 0) lua_pushstring(L, transfers[m->def.apic]);
    else if (strcmp(k, "stress") == 0) lua_pushstring(L, stresses[m->def.stress]);
    else if (strcmp(k, "threads") == 0) lua_pushinteger(L, m->def.threads);
    else if (strcmp(k, "axisymmetric") == 0) lua_pushboolean(L, m->def.axisym);
    else if (strcmp(k, "courant") == 0) lua_pushnumber(L, m->def.courant);
    else if (strcmp(k, "damping") == 0) lua_pushnumber(L, m->def.damping);
    else if (strcmp(k, "viscous_limit") == 0) lua_pushnumber(L, m->def.visc_limit);
    else if (strcmp(k, "substeps") == 0) lua_pushinteger(L, lm_subcycle_count(m));
    else if (strcmp(k, "fast_gas") == 0) lua_pushinteger(L, lm_subcycle_fast_gas(m));
    else if (strcmp(k, "gravity") == 0) {
        lua_createtable(L, 2, 0);
        lua_pushnumber(L, m->def.gx);
        lua_rawseti(L, -2, 1);
        lua_pushnumber(L, m->def.gy);
        lua_rawseti(L, -2, 2);
    }
    else {
        luaL_getmetafield(L, 1, "methods");
        la_getfield(L, -1, k);
        if (lua_isnil(L, -1)) return luaL_error(L, "sim has no field or method '%s'", k);
    }
    return 1;
}

/* Live simulation parameters, applied between steps like material changes
 * and logged the same way: dt (the clock stays exact), gravity (the
 * potential energy keeps its original datum and gravity: it is only
 * meaningful while gravity is unchanged), pic, courant, damping. */
static int sim_newindex(lua_State *L)
{
    if (la_check_sim_any(L, 1)->s3) return la_sim3_newindex(L);
    la_sim *s = la_check_sim(L, 1);
    const char *k = luaL_checkstring(L, 2);
    lm_sim *m = s->sim;
    if (strcmp(k, "dt") == 0) {
        double dt = luaL_checknumber(L, 3);
        if (!(dt > 0) || !isfinite(dt)) return luaL_error(L, "sim.dt must be positive (got %f)", dt);
        /* checked as at the start of a run (s.dt = 1e300 was not): a dt
         * past the Courant limit is refused and the old one kept */
        if (lm_sim_try_dt(m, dt) != LM_OK) return luaL_error(L, "sim.%s", m->err);
    } else if (strcmp(k, "gravity") == 0) {
        luaL_checktype(L, 3, LUA_TTABLE);
        lua_rawgeti(L, 3, 1);
        lua_rawgeti(L, 3, 2);
        double gx = luaL_checknumber(L, -2), gy = luaL_checknumber(L, -1);
        if (lm_sim_set_gravity(m, gx, gy) != LM_OK) return luaL_error(L, "sim.%s", m->err);
        lua_pop(L, 2);
    } else if (strcmp(k, "pic") == 0) {
        if (lm_sim_set_pic(m, luaL_checknumber(L, 3)) != LM_OK)
            return luaL_error(L, "sim.%s", m->err);
    } else if (strcmp(k, "courant") == 0) {
        if (lm_sim_set_courant(m, luaL_checknumber(L, 3)) != LM_OK)
            return luaL_error(L, "sim.%s", m->err);
    } else if (strcmp(k, "damping") == 0) {
        if (lm_sim_set_damping(m, luaL_checknumber(L, 3)) != LM_OK)
            return luaL_error(L, "sim.%s", m->err);
    } else {
        return luaL_error(L, "sim.%s cannot be changed (changeable: dt, gravity, pic, courant, "
                          "damping)", k);
    }
    la_log_change(L, "sim", k, 3);
    return 0;
}

static int sim_tostring(lua_State *L)
{
    if (la_check_sim_any(L, 1)->s3) return la_sim3_tostring(L);
    la_sim *s = la_check_sim(L, 1);
    lua_pushfstring(L, "lamina.sim (%d x %d cells, %d particles, t = %f)",
                    s->sim->grid.nx, s->sim->grid.ny, (int)s->sim->p.n, s->sim->t);
    return 1;
}

/* The step count is sim.nstep and sim:step(n) the method: the count was
 * once sim.step too, which took a __call on every number to let both work
 * (docs/design.md: the one rename of the contract). Queries have their own
 * names: sim:courant_number() beside the setting sim.courant. */
void la_open_sim(lua_State *L)
{
    static const luaL_Reg meta[] = {{"__gc", sim_gc},
                                    {"__index", sim_index},
                                    {"__newindex", sim_newindex},
                                    {"__tostring", sim_tostring},
                                    {NULL, NULL}};
    static const luaL_Reg methods[] = {{"body", la_sim_body},
                                       {"membrane", la_sim_membrane},
                                       {"record", la_sim_record},
                                       {"vtk", la_sim_vtk},
                                       {"checkpoint", la_sim_checkpoint},
                                       {"every", sim_every},
                                       {"at", sim_at},
                                       {"run", sim_run},
                                       {"step", sim_step},
                                       {"energy", sim_energy},
                                       {"momentum", sim_momentum},
                                       {"hash", sim_hash},
                                       {"courant_number", sim_courant},
                                       {"frame", la_sim_frame},
                                       {NULL, NULL}};
    la_new_metatable(L, LA_SIM);
    luaL_setfuncs(L, meta, 0);
    luaL_newlib(L, methods);
    la_contact_methods(L);   /* sim:contact, sim:contact_info (l_contact.c) */
    la_link_methods(L);      /* sim:link (l_link.c) */
    la_relax_methods(L);     /* sim:relax (l_relax.c) */
    lua_setfield(L, -2, "methods");
    la_sim3_methods(L);      /* a 3D sim's (l_sim3.c) */
    lua_setfield(L, -2, "methods3");
    lua_pop(L, 1);
}
