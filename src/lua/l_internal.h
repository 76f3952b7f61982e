/* l_internal.h - shared by the binding files (not a public header). */
#ifndef LAMINA_L_INTERNAL_H
#define LAMINA_L_INTERNAL_H

#include <lauxlib.h>
#include <lua.h>
#include <stdio.h>

#include "lamina_lua.h"
#include "mpm.h"

#define LA_MATERIAL "lamina.material"
#define LA_REGION "lamina.region"
#define LA_SIM "lamina.sim"
#define LA_BODY "lamina.body"
#define LA_REGION3 "lamina.region3"
#define LA_BODY3 "lamina.body3"

/* l_args.c: constructor tables. Every constructor takes one table of named
 * arguments and rejects a key it does not know, by name, at the script's
 * line (docs/design.md, "Conventions"). */
/* lua_getfield without metamethods on tables (l_args.c says why). */
int la_getfield(lua_State *L, int idx, const char *key);
/* t[key] of the table t at idx (la_getfield), or a new empty table stored
 * there when it is not a table; pushed (l_subtable.c). */
void la_subtable(lua_State *L, int idx, const char *key);
void la_check_table(lua_State *L, int idx, const char *fn);
void la_check_keys(lua_State *L, int idx, const char *fn, const char *const keys[]);
int la_has(lua_State *L, int idx, const char *key);
double la_number(lua_State *L, int idx, const char *fn, const char *key);
/* Calls the function at idx with arg: 1 with its two results in *a, *b
 * when both are finite numbers, else 0 (the caller names the fault). */
int la_call_pair(lua_State *L, int idx, double arg, double *a, double *b);
double la_opt_number(lua_State *L, int idx, const char *fn, const char *key, double def);
const char *la_opt_string(lua_State *L, int idx, const char *fn, const char *key,
                          const char *def);
/* A {a, b} pair of numbers at key. */
void la_pair(lua_State *L, int idx, const char *fn, const char *key, double *a, double *b);
/* t.velocity of the table at idx: a function (left on the stack; its
 * index is returned) or {vx, vy} into *vx, *vy (0: none given, or a pair). */
int la_opt_velocity(lua_State *L, int idx, const char *fn, double *vx, double *vy);
/* The option's index in names[] or a named error. */
int la_option(lua_State *L, const char *fn, const char *key, const char *value,
              const char *const names[]);
/* A list of {x, y} points, as the table at 1 itself or its `points` key
 * (lamina.polygon, lamina.polyline): its stack index; *n points, >= min. */
int la_point_list(lua_State *L, const char *fn, int min, int *n);
void la_point_at(lua_State *L, int list, int i, const char *fn, double *x, double *y);
lamina_run *la_run(lua_State *L);
/* l_param.c: lamina.param(name, default) */
int la_param(lua_State *L);
/* luaL_newmetatable with __metatable set: every userdata type uses it. */
int la_new_metatable(lua_State *L, const char *name);
/* A class: la_new_metatable(name) with the metamethods meta and a method
 * table methods as its __index; the metatable is left on the stack. */
void la_new_class(lua_State *L, const char *name, const luaL_Reg *meta,
                  const luaL_Reg *methods);
/* A handle's __tostring: "CLASS N", N its 1-based index in the sim (pins,
 * links). */
int la_push_handle_name(lua_State *L, const char *name, int index);
/* la_new_class with the method table at field: "methods" for a class
 * whose own __index function looks in it (the body handles). */
void la_new_class_in(lua_State *L, const char *name, const luaL_Reg *meta,
                     const luaL_Reg *methods, const char *field);
/* l_handle.c: a handle into a sim (a body, a pin): a userdata of class
 * meta holding the engine's index, with the sim at sidx as uservalue 1
 * (a handle keeps its sim alive) and nuv uservalues in all. */
void la_handle_push(lua_State *L, const char *meta, int sidx, int index, int nuv);
/* The index held by the handle at idx; its sim pushed. */
int la_handle_check(lua_State *L, int idx, const char *meta);

/* l_provenance.c: the tEXt chunks of every image (Software, lamina:script,
 * lamina:script-hash, lamina:set); la_provenance pushes one string that must
 * stay on the stack while text is used. */
#include "render.h"
typedef struct la_prov {
    char version[64], hash[32];
    lr_text_chunk text[4];
} la_prov;
void la_provenance(lua_State *L, la_prov *p);
/* Counts an image written and remembers its folder for the run's summary. */
void la_note_image(lua_State *L, const char *path);

/* l_alloc.c: luaL_newstate with the run's memory cap (run may be NULL) */
lua_State *la_new_state(lamina_run *run);

/* l_sandbox.c: the standard library a script gets (docs/design.md, "A script
 * is untrusted input"); la_load_script loads a regular text file only. */
void la_open_sandbox(lua_State *L, const char *script);
int la_load_script(lua_State *L, const char *path);
/* l_pattern.c: string.find/match/gmatch/gsub refuse a call whose worst-case
 * backtracking passes ~1e9 steps (C code cannot be interrupted) */
void la_guard_patterns(lua_State *L);

/* l_path.c: every file a script names is checked here before it is
 * written (inside the output root, no NUL or control character, not a
 * device, nor a file lamina did not write; hidden names refused; the path
 * noted in ROOT/.lamina-outputs); returns the string at idx. la_opt_output_path reads table key
 * `key` (NULL when absent). la_check_text refuses control characters in a
 * name that goes into a file's text (CSV headers). */
const char *la_check_output_path(lua_State *L, const char *fn, int idx);
/* l_print.c: `print` writes as la_write_clean (lamina_lua.h) does. */
void la_open_print(lua_State *L);
/* the same confinement for a file a script reads (no ownership check) */
const char *la_check_input_path(lua_State *L, const char *fn, int idx);
/* A file that comes with the script (a mesh, lamina.mesh): a relative name
 * is taken from the script's folder; it must resolve (links followed) to a
 * regular file inside the script's folder or the output root, no name
 * under them starting with a dot, at most max bytes. real (PATH_MAX) gets
 * its resolved path, *size its size; returns the name as given. */
const char *la_check_asset_path(lua_State *L, const char *fn, int idx, size_t max, char *real,
                                size_t *size);
/* l_sandbox.c: the script's folder (its real path) into out: 1, or 0 when
 * there is no script (the working directory stands for it then). */
int la_script_folder(lua_State *L, char *out, size_t len);
/* l_outputs.c: whether lamina wrote the existing file `where` (rel: its
 * path under root), and noting rel as lamina's (0, or -1 with err) */
int la_output_owned(lua_State *L, const char *root, const char *rel, const char *where);
int la_output_note(lua_State *L, const char *root, const char *rel, char *err, size_t len);
const char *la_opt_output_path(lua_State *L, int idx, const char *fn, const char *key);
void la_check_text(lua_State *L, const char *fn, const char *what, const char *s);
/* a CSV column name: letters, digits, space and _ . - ( ) [ ] / only */
void la_check_csv_name(lua_State *L, const char *fn, const char *what, const char *s);

/* l_material.c */
void la_open_material(lua_State *L);
int la_elastic(lua_State *L);
int la_membrane_material(lua_State *L);
int la_gas(lua_State *L);
int la_linear_fluid(lua_State *L);
/* A material as the script holds it: its definition, which each sim it is
 * given to copies (lm_sim_add_material); a live change (mat.E = 2000)
 * goes to every such sim through lm_sim_set_material. */
typedef struct la_material {
    lm_material def;
    int plane_given;            /* `plane` was written: refused in 3D (l_body3.c) */
} la_material;
la_material *la_check_material(lua_State *L, int idx);
/* The engine's index of the material at midx in the sim at sidx, added
 * to it (and remembered, for live changes) the first time; a Lua error
 * prefixed fn if the engine refuses it. */
int la_sim_material(lua_State *L, int sidx, int midx, const char *fn);
/* After a checkpoint's restore replaced the sim's materials: the
 * script's materials take the restored values, and so do the other sims
 * they were given to. */
void la_material_sync(lua_State *L, int sidx);

/* l_region.c */
void la_open_region(lua_State *L);
int la_disk(lua_State *L);
int la_rect(lua_State *L);
int la_polygon(lua_State *L);
lm_region *la_test_region(lua_State *L, int idx);

/* l_sim.c */
typedef struct la_event {
    double interval;            /* 0: once (sim:at) */
    double t0;                  /* first firing */
    double k;                   /* index of the next multiple due (a double:
                                   interval / dt can exceed any long) */
    double next;
    int ref;                    /* the function, in the sim's uservalue */
    int done;
} la_event;

typedef struct la_pin_fn {
    int pin;                    /* the engine's pin */
    int ref;                    /* its velocity function, in the uservalue */
} la_pin_fn;

/* l_ref.c: one body's reference positions (sim:frame{scale = k}) */
typedef struct la_ref_body {
    size_t n;                   /* its points captured (the first n) */
    double *x, *y;
} la_ref_body;

typedef struct la_sim {
    lm_sim *sim;
    int running;                /* inside run/step: no nested runs */
    int mass_auto;              /* mass = "auto" (the default): resolved as each
                                   run starts (l_sim.c, mass_resolve) */
    la_event *ev;
    int nev, capev;
    la_pin_fn *pinf;            /* pins driven by a function of time */
    int npinf;
    int index;                  /* 1 + the sims the script made before it */
    char *ck_file;              /* sim:checkpoint (l_checkpoint.c) */
    unsigned long long warned_bunched;   /* bodies warned of bunched points (bit b) */
    int warned_energy;          /* said once: the energy rose (energy_watch.c) */
    int warned_leak;            /* said once: gas crossed a membrane (l_leak_watch.c) */
    signed char *leak_side;     /* leak_nb^2: which side of membrane m gas g keeps */
    int leak_nb;
    long leak_step;             /* the step last checked */
    double ck_every, ck_next;
    la_ref_body *ref;           /* per body, nref of them (l_ref.c) */
    int nref;
    struct la_sim3 *s3;         /* lamina.sim{dim = 3}: the 3D run (l_sim3.h); sim
                                   is NULL then */
} la_sim;

/* l_ref.c: captures the points of s's bodies that have no reference yet
 * (called as a run starts and before a --restart replaces the state);
 * la_ref_scaled fills x, y (p.n each) with X0 + k (x - X0), a point without
 * a reference where it is; la_ref_free when the sim is collected. */
void la_ref_capture(lua_State *L, la_sim *s);
void la_ref_scaled(const la_sim *s, double k, double *x, double *y);
void la_ref_free(la_sim *s);

/* Gas more than a quarter cell across a closed membrane, said once
 * (l_leak_watch.c); called every step, it checks when LA_LEAK_EVERY steps
 * have passed since its last check or a body was added. */
#define LA_LEAK_EVERY 20
void la_leak_watch(lua_State *L, la_sim *s);
void la_option_warn(const la_sim *s);
struct lm3_sim;
void la_option_warn3(const struct lm3_sim *sim);   /* the 3D sims' share */

/* A warning line to stderr (clearing the progress line) and the run log. */
void la_warn(lua_State *L, const char *line);

void la_open_sim(lua_State *L);
int la_sim_new(lua_State *L);
la_sim *la_check_sim(lua_State *L, int idx);
/* Either dimension (la_check_sim refuses a 3D sim naming the method). */
la_sim *la_check_sim_any(lua_State *L, int idx);
/* Keeps the value at idx alive as long as the sim at sidx (its uservalue). */
void la_sim_keep(lua_State *L, int sidx, int idx);
/* {kinetic, strain, internal, potential, total} */
void la_push_energy(lua_State *L, lm_energy e);

/* Calls the function at fidx with the sim at `first` and then every
 * `interval` (0: once), between steps. */
void la_sim_add_event(lua_State *L, int sidx, double first, double interval, int fidx);
/* The first t0 + k interval after now (k updated, kept increasing), in
 * O(1); the next representable time when rounding leaves none. */
double la_next_multiple(double t0, double interval, double *k, double now);
/* Refuses an interval that is not a positive finite time, or too small for
 * the clock at t (t + interval == t, or more than 2^53 multiples to t). */
void la_check_interval(lua_State *L, const char *fn, const char *what, double interval,
                       double t);

/* l_pin.c: body:pin{...} and the pin handle. la_sim_add_pin_function
 * (l_sim.c) keeps a driven pin's function; la_pins_update calls them before
 * each step. */
int la_body_pin(lua_State *L);
void la_open_pin(lua_State *L);
void la_sim_add_pin_function(lua_State *L, int sidx, int pin, int fidx);
void la_pins_update(lua_State *L, int sidx, la_sim *s);

/* l_contact.c: adds sim:contact and sim:contact_info to the method table
 * at the top of the stack. */
void la_contact_methods(lua_State *L);
/* l_relax.c: sim:relax{...}, steps with grid damping until the motion has
 * died down; la_sim_advance (l_sim.c) is sim:step(n) for it (sim at
 * stack index 1). */
void la_relax_methods(lua_State *L);
void la_sim_advance(lua_State *L, la_sim *s, long nsteps);
/* l_link.c: sim:link{...} and the link handle. */
void la_link_methods(lua_State *L);
void la_open_link(lua_State *L);

/* l_checkpoint.c: sim:checkpoint{...}; la_checkpoint_due writes one when
 * due (after the step's callbacks); la_checkpoint_restore replaces the
 * state of the sim at sidx by `lamina run --restart FILE`'s, once, at its
 * first run/step; la_sim_skip_due (l_sim.c) marks the events due at or
 * before the present time as fired. */
int la_sim_checkpoint(lua_State *L);
void la_checkpoint_due(lua_State *L, int sidx, la_sim *s);
void la_checkpoint_restore(lua_State *L, int sidx, la_sim *s);
void la_sim_skip_due(la_sim *s);
/* l_sim.c: runs the events due at the sim's clock (either dimension), the
 * sim at stack index 1; how many ran. */
int la_sim_fire_due(lua_State *L, la_sim *s);

/* Raises "simulation failed: why" as a LAMINA_FAIL_UNSTABLE failure. */
void la_raise_sim_failure(lua_State *L, const char *why);

/* l_run_guard.c: the one way out of a run (issue 33 item 4). advance()
 * calls la_run_guard_begin (the sim running), runs its steps in a protected
 * call and then la_run_guard_end, failed or not: the running state cleared,
 * the progress line ended (when g->progress), the records written; a
 * failure (the error on top) recorded, then raised again. la_fail_raise
 * raises the value on top as a failure of the code given (LAMINA_FAIL_*);
 * any other error ending a run is LAMINA_FAIL_SCRIPT. la_fail_note_escape
 * (the top-level message handler) notes whether the error at idx that ends
 * the script is the recorded failure. */
typedef struct la_run_guard {
    la_sim *s;
    int sidx;                   /* the sim's stack index */
    int progress;               /* la_progress_begin has returned */
    const lm_sim *outer;        /* the run that was active before */
    struct la_run_guard *outer_guard;
    char where[256];            /* "script.lua:12: ", where sim:run was called */
} la_run_guard;
void la_run_guard_begin(lua_State *L, la_run_guard *g, int sidx, la_sim *s);
void la_run_guard_end(lua_State *L, la_run_guard *g, int failed);
int la_fail_raise(lua_State *L, int code);
/* la_fail_raise of a message formatted as luaL_error's, starting with where
 * the script called the run in progress (else luaL_where(L, 1)). */
int la_fail_raisef(lua_State *L, int code, const char *fmt, ...);
void la_fail_note_escape(lua_State *L, int idx);

/* l_record.c */
int la_sim_record(lua_State *L);
/* l_vtk.c: sim:vtk{file, every}, the run for ParaView */
int la_sim_vtk(lua_State *L);
void la_open_record(lua_State *L);
/* Writes the CSV files of the sim's recorders (at the end of run/step). */
void la_record_flush(lua_State *L, int sidx);
/* Checkpoints: the recorders of the sim at sidx (1-based, creation order),
 * their rows, and replacing them (-1 if the columns differ). */
int la_record_count(lua_State *L, int sidx);
void la_record_rows(lua_State *L, int sidx, int i, int *ncols, size_t *nrows,
                    const double **rows);
int la_record_set_rows(lua_State *L, int sidx, int i, int ncols, size_t nrows,
                       const double *rows);

/* l_body.c */
void la_open_body(lua_State *L);
int la_sim_body(lua_State *L);
/* Pushes a handle for body bi of the sim at sidx; name at nameidx (0: none). */
void la_push_body(lua_State *L, int sidx, int bi, int nameidx);
/* The body handle at idx and its simulation. */
int la_check_body(lua_State *L, int idx, lm_sim **sim);

/* l_csv.c: lamina.read_csv(path) -> columns, names, rows */
int la_read_csv(lua_State *L);

/* l_frame_phi.c: membrane:phi(x, y), the phi sim:frame{phi = true} draws */
int la_body_phi(lua_State *L);

/* l_membrane.c */
int la_sim_membrane(lua_State *L);

/* l_frame.c */
int la_sim_frame(lua_State *L);
const char *la_frame_label(lua_State *L, int idx, const char *fn, double t, long step);
lr_backend la_frame_backend(lua_State *L, int idx, const char *fn, const char *file);
int la_vtk_arrays(size_t nd, size_t nconn, size_t ntypes, double **d, int64_t **conn,
                  uint8_t **types, const char *path, char *err, size_t errlen);
/* A grid's arrays for a .vtu (2D quads, 3D hexahedra): nn nodes' mass,
 * velocity, force and xyz in one buffer; nc cells' connectivity (corners
 * a cell), offsets and types. la_vtk_grid_alloc: all or none (-1 and err
 * out of memory); la_vtk_grid_write writes the .vtu and frees them. */
typedef struct la_vtk_grid {
    size_t nn, nc;
    double *mass, *vel, *force, *xyz;
    int64_t *conn, *offs;
    uint8_t *types;
} la_vtk_grid;
int la_vtk_grid_alloc(la_vtk_grid *g, size_t nn, size_t nc, int corners, const char *path,
                      char *err, size_t errlen);
int la_vtk_grid_write(const char *path, la_vtk_grid *g, char *err, size_t errlen);

/* l_plot.c: lamina.plot{...}, time-series plots to PNG and CSV */
int la_plot(lua_State *L);

/* l_report.c: lamina.report{name = value, ...} (contract); writes the
 * file of `lamina run --report FILE` (lamina_run.report_file). */
int la_report(lua_State *L);

/* l_normals.c: sets lamina.normals and lamina.figure in the table on top */
void la_open_normals(lua_State *L);

/* l_progress.c, l_interrupt.c: hooks of advance() (l_sim.c). begin/end
 * bracket a run or step call of the sim at sidx; tick follows every step:
 * it counts the step, shows progress, polls, and returns nonzero when the
 * run must stop at this boundary (Ctrl-C, watch --steps, a changed script);
 * la_interrupt_raise then raises "interrupted at t = ..., step ...". */
void la_progress_begin(lua_State *L, int sidx, long nsteps);
int la_progress_tick(lua_State *L, const lm_sim *sim);
void la_progress_end(lua_State *L);
int la_interrupt_raise(lua_State *L, const lm_sim *sim);

/* l_runlog.c: the run log. A live parameter change (from sim:at, sim:every
 * or the repl's prompt) is echoed to stderr and run->log with its time and
 * step, and recorded for lamina.changes(). */
void la_log_change(lua_State *L, const char *what, const char *key, int validx);
int la_changes(lua_State *L);
/* The simulation that stepped or paused last (the prompt's clock). */
void la_set_last_sim(lua_State *L, int sidx);
const lm_sim *la_last_sim(lua_State *L);

/* l_pause.c: lamina.pause() and lamina.resume() (the repl's script) */
int la_pause(lua_State *L);
int la_resume(lua_State *L);

#endif
