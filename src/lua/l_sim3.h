/* l_sim3.h - the Lua layer's 3D run (docs/3d.md "Lua API"): what a
 * lamina.sim{dim = 3} holds beside the la_sim it shares with 2D (events,
 * the run guard, checkpoints' bookkeeping), and the pieces its files
 * share. */
#ifndef LAMINA_L_SIM3_H
#define LAMINA_L_SIM3_H

#include "l_internal.h"
#include "mpm3.h"

/* A body: its particles are the range [first, first + n) of the engine's
 * arrays (bodies are added whole and never removed). */
typedef struct la_body3rec {
    size_t first, n;
    int mat;
} la_body3rec;

typedef struct la_sim3 {
    lm3_sim *sim;
    la_body3rec *bodies;
    int nbodies, capbodies;
    size_t charged;             /* bytes charged to the process budget for the
                                   engine's arrays (docs/security.md "Memory") */
} la_sim3;

/* l_sim3.c */
int la_sim3_new(lua_State *L);                 /* lamina.sim{dim = 3, ...} at 1 */
void la_sim3_free(la_sim3 *s3);
int la_sim3_index(lua_State *L);               /* __index, __newindex, __tostring */
int la_sim3_newindex(lua_State *L);
int la_sim3_tostring(lua_State *L);
void la_sim3_methods(lua_State *L);            /* pushes the method table */
/* Charges the budget up to `bytes` for the engine's arrays (0, or a Lua
 * error naming what was asked and the cap). */
void la_sim3_charge(lua_State *L, la_sim3 *s3, size_t bytes, const char *fn);
/* The sim at idx, 3D (a Lua error naming fn otherwise). */
la_sim3 *la_check_sim3(lua_State *L, int idx, const char *fn);
/* Three finite numbers at key of the table at idx: 1, or 0 when absent. */
int la_triple(lua_State *L, int idx, const char *fn, const char *key, double v[3]);
/* {kinetic, strain, internal (the gases' sum m e), potential, total} */
void la_sim3_push_energy(lua_State *L, const lm3_energy *e);
/* Refuses a 2D-only method called on a 3D sim (and the reverse), naming it. */
int la_sim3_refuse(lua_State *L);

/* A lamina.gas as the 3D engine's material (kind LM3_GAS, the same
 * constants). */
lm3_material la_gas3(const lm_material *m);
/* A live change of material k (mat.E, mat.nu; a gas's mu, av:
 * l_material.c): 0, or -1 with the engine's reason in s3->sim->err */
int la_sim3_set_material(la_sim3 *s3, int k, const lm_material *m);

/* l_sim3_run.c: run, step, every, at (the 2D semantics) */
int la_sim3_run(lua_State *L);
int la_sim3_step(lua_State *L);
int la_sim3_every(lua_State *L);
int la_sim3_at(lua_State *L);

/* l_vtk3.c: sim:vtk's particle and grid pieces (0, or -1 with err) */
int la_vtk3_write_particles(const la_sim3 *s3, const char *path, char *err, size_t errlen);
int la_vtk3_write_grid(const la_sim3 *s3, const char *path, char *err, size_t errlen);
/* the membranes' points (a third piece, when the sim has membranes) */
int la_vtk3_has_membranes(const la_sim3 *s3);
int la_vtk3_write_membranes(const la_sim3 *s3, const char *path, char *err, size_t errlen);

/* l_body3.c */
int la_sim3_body(lua_State *L);
void la_open_body3(lua_State *L);

/* l_pin3.c: body:pin on a 3D body (the range first, n of the sim's
 * particles; the body at 1, its options at 2); la_pins3_update before each
 * step (the driven pins' functions, then the held points' velocities) */
int la_body3_pin(lua_State *L, la_sim3 *s3, size_t first, size_t n);
void la_pins3_update(lua_State *L, int sidx, la_sim *s);
void la_open_pin3(lua_State *L);

/* l_membrane3.c: sim:membrane on a 3D sim, lamina.sphere, lamina.rect3,
 * the membrane handle; the bytes the membrane points hold (charged with
 * the particles'); sim:checkpoint (the state file holds the membranes) */
int la_sim3_membrane(lua_State *L);
int la_sphere(lua_State *L);
int la_rect3(lua_State *L);
size_t la_membrane3_bytes(const la_sim3 *s3);
int la_sim3_checkpoint(lua_State *L);
void la_open_membrane3(lua_State *L);

/* The body at idx (a 3D body's handle; a Lua error otherwise), l_body3.c;
 * the engine's index of the membrane at idx, l_membrane3.c. */
const la_body3rec *la_check_body3(lua_State *L, int idx, la_sim3 **s3);
int la_check_membrane3(lua_State *L, int idx, la_sim3 **s3);

/* l_membrane3_gas.c: a gas inside a closed membrane (docs/3d.md "A gas
 * inside a 3D membrane"): membrane:enclosed_volume(), membrane:escaped(gas),
 * gas:pressure(membrane) */
int la_membrane3_volume(lua_State *L);
int la_membrane3_escaped(lua_State *L);
int la_gas3_pressure(lua_State *L);

/* l_region3.c: lamina.ball, lamina.box, lamina.cylinder */
int la_ball(lua_State *L);
int la_box(lua_State *L);
int la_cylinder(lua_State *L);
void la_open_region3(lua_State *L);
lm3_region *la_test_region3(lua_State *L, int idx);

#endif
