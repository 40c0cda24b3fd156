/* case.c: the case-script loader. A case is a Lua 5.4 script run in a sandbox (base, math,
 * string and table only; no io, os, package, debug, load, loadfile or dofile) whose declarations
 * (param, domain, particles, scheme, fluid, fill, wall, box_wall, sphere_wall, cylinder_wall,
 * stl_wall, arc, circle, inflow, outflow, probe, profile, force, run, render) fill a struct
 * scene. Every declaration checks its keys: an unknown key is an error naming the script line and
 * the nearest known key. */
#include "case.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "interrupt.h"
#include "spectrum.h"
#include "spell.h"

/* The sandbox's limits at work: the bytes the Lua state holds (its allocator refuses beyond the
 * ceiling) and the instructions of the current entry into the script (a count hook every
 * SANDBOX_HOOK_EVERY instructions raises an error beyond the budget). */
struct sandbox {
  lua_State *L;
  size_t used, limit;      /* bytes */
  long long count, budget; /* instructions of this entry, and the most it may run */
  const char *path;        /* the script */
  const char *phase;       /* what runs: "the case script", "metrics()", ... */
  char phase_buf[SCENE_NAME + 48];
  int refused;          /* the allocator refused a block (memory ceiling) */
  size_t refused_bytes; /* the size it was asked for */
  char where[192];      /* file:line of the Lua code that asked, or "" */
};

struct case_script {
  lua_State *L;
  struct sandbox sb; /* the allocator's state: lives as long as L */
  int dim;           /* the scene's: the fill functions take (x, y) or (x, y, z) */
};

enum { SANDBOX_HOOK_EVERY = 1000 };

void case_limits_default(struct case_limits *l)
{
  l->instructions = 1e9;
  l->memory = 512.0 * 1024.0 * 1024.0;
}

/* The first Lua function on the stack (the code that asked for memory or ran too long). */
static void lua_code_at(lua_State *L, char *buf, size_t size)
{
  lua_Debug ar;
  buf[0] = '\0';
  for (int level = 0; level < 12 && lua_getstack(L, level, &ar); ++level) {
    if (!lua_getinfo(L, "Sl", &ar) || ar.currentline <= 0) continue;
    snprintf(buf, size, "%s:%d", ar.short_src, ar.currentline);
    return;
  }
}

/* lua_Alloc with a ceiling: a block that would take the state beyond sb->limit is refused (Lua
 * then raises a memory error, LUA_ERRMEM, which sandbox_call reports). */
static void *sandbox_alloc(void *ud, void *ptr, size_t osize, size_t nsize)
{
  struct sandbox *sb = ud;
  const size_t old = ptr != NULL ? osize : 0;
  if (nsize == 0) {
    free(ptr);
    sb->used -= old;
    return NULL;
  }
  if (nsize > old && (nsize - old > sb->limit || sb->used + (nsize - old) > sb->limit)) {
    if (!sb->refused && sb->L != NULL) lua_code_at(sb->L, sb->where, sizeof sb->where);
    sb->refused = 1;
    sb->refused_bytes = nsize;
    return NULL;
  }
  void *p = realloc(ptr, nsize);
  if (p != NULL) sb->used = sb->used - old + nsize;
  return p;
}

/* The count hook: the instruction budget of the current entry. */
static void sandbox_hook(lua_State *L, lua_Debug *ar)
{
  void *ud = NULL;
  lua_getallocf(L, &ud);
  struct sandbox *sb = ud;
  sb->count += SANDBOX_HOOK_EVERY;
  const int sig = interrupt_signal();
  if (sb->count <= sb->budget && sig == 0) return;
  char where[192] = "";
  if (lua_getinfo(L, "Sl", ar) && ar->currentline > 0)
    snprintf(where, sizeof where, "%s:%d: ", ar->short_src, ar->currentline);
  else
    lua_code_at(L, where, sizeof where);
  if (sig != 0) luaL_error(L, "%s%s interrupted (%s)", where, sb->phase, interrupt_name(sig));
  luaL_error(L,
             "%s%s ran out of instructions: more than its budget of %I (an endless loop?); "
             "--case-instructions N raises the budget",
             where, sb->phase, (lua_Integer)sb->budget);
}

/* Call the function under its nargs arguments on the stack, as lua_pcall, with the instruction
 * budget started afresh; `phase` says what runs. A failure is logged once, with the file, the
 * line and what ran out. */
static enum clsph_status sandbox_call(struct sandbox *sb, int nargs, int nresults,
                                      const char *phase)
{
  enum clsph_status st = CLSPH_OK;
  lua_State *L = sb->L;
  sb->phase = phase;
  sb->count = 0;
  sb->refused = 0;
  sb->where[0] = '\0';
  const int err = lua_pcall(L, nargs, nresults, 0);
  if (err == LUA_ERRMEM || (err != LUA_OK && sb->refused)) {
    log_error("%s%s%s ran out of memory: a block of %.0f MiB would take it past the case "
              "sandbox's ceiling of %.0f MiB (--case-memory MIB raises it)",
              sb->where[0] ? sb->where : sb->path, ": ", phase,
              (double)sb->refused_bytes / 1048576.0, (double)sb->limit / 1048576.0);
    lua_pop(L, 1);
    st = CLSPH_E_INPUT;
  } else if (err != LUA_OK) {
    log_error("%s", lua_tostring(L, -1));
    lua_pop(L, 1);
    st = CLSPH_E_INPUT;
  }
  sb->phase = NULL;
  return st;
}

#define FILL_VELOCITY "clsph.fill_velocity" /* registry: the fills' velocity functions */
#define FILL_PRESSURE "clsph.fill_pressure" /* and their pressure and density functions */
#define FILL_DENSITY  "clsph.fill_density"
#define FILL_K        "clsph.fill_k" /* and the turbulence's k and ε functions */
#define FILL_EPS      "clsph.fill_epsilon"
static const char *const fill_scalar_key[4] = {"pressure", "density", "k", "epsilon"};
static const char *const fill_scalar_reg[4] = {FILL_PRESSURE, FILL_DENSITY, FILL_K, FILL_EPS};

/* scene_velocity_fn.eval: u, v (u, v, w in 3-D) = the velocity function of fill `region` at x. */
static enum clsph_status fill_velocity(void *ctx, int region, const double *x, double *v)
{
  enum clsph_status st = CLSPH_OK;
  struct case_script *cs = ctx;
  lua_State *L = cs->L;
  const int top = lua_gettop(L);
  lua_getfield(L, LUA_REGISTRYINDEX, FILL_VELOCITY);
  CLSPH_CHECK(lua_istable(L, -1) && lua_rawgeti(L, -1, region + 1) == LUA_TFUNCTION, CLSPH_E_INPUT,
              "fill %d has no velocity function", region + 1);
  const int dim = cs->dim;
  for (int a = 0; a < dim; ++a) lua_pushnumber(L, x[a]);
  snprintf(cs->sb.phase_buf, sizeof cs->sb.phase_buf, "the velocity function of fill %d",
           region + 1);
  CLSPH_TRY(sandbox_call(&cs->sb, dim, dim, cs->sb.phase_buf));
  int numbers = 1, finite = 1;
  for (int a = 0; a < dim; ++a) numbers &= lua_isnumber(L, a - dim);
  CLSPH_CHECK(numbers, CLSPH_E_INPUT,
              "the velocity function returned %s, %s%s%s: it must return %s",
              luaL_typename(L, -dim), luaL_typename(L, 1 - dim), dim == 3 ? ", " : "",
              dim == 3 ? luaL_typename(L, -1) : "",
              dim == 3 ? "three numbers u, v, w" : "two numbers u, v");
  for (int a = 0; a < dim; ++a) {
    v[a] = lua_tonumber(L, a - dim);
    finite &= isfinite(v[a]) != 0;
  }
  CLSPH_CHECK(finite || dim == 3, CLSPH_E_INPUT,
              "the velocity function returned (%g, %g): it must be finite", v[0], v[1]);
  CLSPH_CHECK(finite, CLSPH_E_INPUT,
              "the velocity function returned (%g, %g, %g): it must be finite", v[0], v[1], v[2]);
done:
  lua_settop(L, top);
  return st;
}

/* scene_velocity_fn.scalar: the pressure (what = 0), density (1), k (2) or ε (3) function of
 * fill `region` at x. */
static enum clsph_status fill_scalar(void *ctx, int region, int what, const double *x, double *v)
{
  enum clsph_status st = CLSPH_OK;
  struct case_script *cs = ctx;
  lua_State *L = cs->L;
  const int top = lua_gettop(L);
  const char *name = fill_scalar_key[what];
  lua_getfield(L, LUA_REGISTRYINDEX, fill_scalar_reg[what]);
  CLSPH_CHECK(lua_istable(L, -1) && lua_rawgeti(L, -1, region + 1) == LUA_TFUNCTION, CLSPH_E_INPUT,
              "fill %d has no %s function", region + 1, name);
  for (int a = 0; a < cs->dim; ++a) lua_pushnumber(L, x[a]);
  snprintf(cs->sb.phase_buf, sizeof cs->sb.phase_buf, "the %s function of fill %d", name,
           region + 1);
  CLSPH_TRY(sandbox_call(&cs->sb, cs->dim, 1, cs->sb.phase_buf));
  CLSPH_CHECK(lua_type(L, -1) == LUA_TNUMBER, CLSPH_E_INPUT,
              "the %s function returned %s: it must return a number", name, luaL_typename(L, -1));
  *v = lua_tonumber(L, -1);
done:
  lua_settop(L, top);
  return st;
}

/* State of one load, reachable from every declaration function (as its upvalue). */
struct loader {
  struct scene *s;
  int nsets;
  char (*set_names)[SCENE_NAME];
  double *set_values;
  int *set_used;
  int line_particles; /* lines of the declarations that must appear once (0: not yet) */
  int line_domain, line_scheme, line_run, line_fluid;
  int nfill; /* regions declared so far, for default names */
};

/* ---- small helpers ---- */

static struct loader *loader_of(lua_State *L)
{
  return lua_touserdata(L, lua_upvalueindex(1));
}

static int current_line(lua_State *L)
{
  lua_Debug ar;
  if (lua_getstack(L, 1, &ar) && lua_getinfo(L, "l", &ar)) return ar.currentline;
  return 0;
}

/* Every string key of the table at idx must be one of `known`; integer keys only when allowed. */
static void check_keys(lua_State *L, int idx, const char *fn, const char *const *known,
                       int positional)
{
  char hint[512];
  lua_pushnil(L);
  while (lua_next(L, idx) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING) {
      const char *k = lua_tostring(L, -2);
      int ok = 0;
      for (int i = 0; known[i] != NULL; ++i) ok |= strcmp(k, known[i]) == 0;
      if (!ok) {
        spell_suggest(k, known, hint, sizeof hint);
        luaL_error(L, "%s: unknown key '%s'%s", fn, k, hint);
      }
    } else if (!positional || !lua_isinteger(L, -2)) {
      luaL_error(L, "%s: unexpected %s key", fn, luaL_typename(L, -2));
    }
    lua_pop(L, 1);
  }
}

/* Number at t[key] (default when absent). */
static double get_number(lua_State *L, int idx, const char *fn, const char *key, double def)
{
  double v = def;
  lua_getfield(L, idx, key);
  if (!lua_isnil(L, -1)) {
    if (!lua_isnumber(L, -1)) luaL_error(L, "%s: '%s' must be a number", fn, key);
    v = lua_tonumber(L, -1);
    if (!isfinite(v)) luaL_error(L, "%s: '%s' must be finite", fn, key);
  }
  lua_pop(L, 1);
  return v;
}

/* Number at t[i] (required). */
static double get_index_number(lua_State *L, int idx, const char *fn, int i, const char *what)
{
  lua_geti(L, idx, i);
  if (!lua_isnumber(L, -1)) luaL_error(L, "%s: %s (entry %d) must be a number", fn, what, i);
  double v = lua_tonumber(L, -1);
  lua_pop(L, 1);
  if (!isfinite(v)) luaL_error(L, "%s: %s must be finite", fn, what);
  return v;
}

/* A point {x, y} at the top of the stack. */
static void to_point(lua_State *L, const char *fn, const char *what, double p[2])
{
  int t = lua_gettop(L);
  if (!lua_istable(L, t) || lua_rawlen(L, t) != 2)
    luaL_error(L, "%s: %s must be a point {x, y}", fn, what);
  p[0] = get_index_number(L, t, fn, 1, what);
  p[1] = get_index_number(L, t, fn, 2, what);
}

/* The value on top of the stack as a point of the scene's dimension: {x, y}, or {x, y, z} after
 * a 3-D domain { }. */
static void to_vec(lua_State *L, const char *fn, const char *what, double *p)
{
  const int dim = loader_of(L)->s->dim, t = lua_gettop(L);
  if (dim == 2) {
    to_point(L, fn, what, p);
    return;
  }
  if (!lua_istable(L, t) || lua_rawlen(L, t) != 3)
    luaL_error(L, "%s: %s must be a point {x, y, z} in a 3-D scene", fn, what);
  for (int a = 0; a < 3; ++a) p[a] = get_index_number(L, t, fn, a + 1, what);
}

/* A sphere { cx, cy, cz, R } or a cylinder { x0, y0, z0, x1, y1, z1, R } (its axis' ends and
 * radius; flat caps) from the sequence at idx, into sh, and its bounding box into box (a cylinder's
 * reaches R √(1 − (d_a/L)²) past its ends along axis a, d the axis and L its length). */
static void get_shape3(lua_State *L, int idx, const char *fn, enum scene_shape3 kind, double sh[7],
                       double box[6])
{
  static const char *const sn[4] = {"cx", "cy", "cz", "R"};
  static const char *const cn[7] = {"x0", "y0", "z0", "x1", "y1", "z1", "R"};
  const int m = kind == SCENE_SPHERE ? 4 : 7;
  if (!lua_istable(L, idx) || (int)lua_rawlen(L, idx) != m)
    luaL_error(L, "%s: give the %s as { %s }", fn, kind == SCENE_SPHERE ? "sphere" : "cylinder",
               kind == SCENE_SPHERE ? "cx, cy, cz, R"
                                    : "x0, y0, z0, x1, y1, z1, R (the axis' ends "
                                      "and the radius)");
  for (int k = 0; k < m; ++k)
    sh[k] = get_index_number(L, idx, fn, k + 1, kind == SCENE_SPHERE ? sn[k] : cn[k]);
  const double r = sh[m - 1];
  if (!(r > 0.0)) luaL_error(L, "%s: the radius R must be positive, not %f", fn, r);
  if (kind == SCENE_SPHERE) {
    for (int a = 0; a < 3; ++a) {
      box[a] = sh[a] - r;
      box[3 + a] = sh[a] + r;
    }
    return;
  }
  const double d[3] = {sh[3] - sh[0], sh[4] - sh[1], sh[5] - sh[2]};
  const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(len > 0.0))
    luaL_error(L, "%s: the cylinder's axis has no length: its ends are one point", fn);
  for (int a = 0; a < 3; ++a) {
    const double c = d[a] / len, e = r * sqrt(fmax(1.0 - c * c, 0.0));
    box[a] = fmin(sh[a], sh[3 + a]) - e;
    box[3 + a] = fmax(sh[a], sh[3 + a]) + e;
  }
}

/* t[key] as a point of the scene's dimension; returns 0 when absent. */
static int get_vec(lua_State *L, int idx, const char *fn, const char *key, double *p)
{
  lua_getfield(L, idx, key);
  int present = !lua_isnil(L, -1);
  if (present) to_vec(L, fn, key, p);
  lua_pop(L, 1);
  return present;
}

/* t[key] as a point; returns 0 when absent. */
static int get_point(lua_State *L, int idx, const char *fn, const char *key, double p[2])
{
  lua_getfield(L, idx, key);
  int present = !lua_isnil(L, -1);
  if (present) to_point(L, fn, key, p);
  lua_pop(L, 1);
  return present;
}

/* t[key] as a vector of the scene's dimension ({x, y}, or {x, y, z} after a 3-D domain { });
 * returns 0 when absent. */
static int get_vector(lua_State *L, int idx, const char *fn, const char *key, double p[3])
{
  const int dim = loader_of(L)->s->dim;
  lua_getfield(L, idx, key);
  const int present = !lua_isnil(L, -1), t = lua_gettop(L);
  if (present) {
    const lua_Unsigned len = lua_istable(L, t) ? lua_rawlen(L, t) : 0;
    if (len == 3 && dim == 2)
      luaL_error(L,
                 "%s: %s has 3 components: a 3-D scene declares its domain { x0, y0, z0, x1, "
                 "y1, z1 } first",
                 fn, key);
    if (len != (lua_Unsigned)dim)
      luaL_error(L, "%s: %s must be a vector %s", fn, key, dim == 3 ? "{x, y, z}" : "{x, y}");
    for (int a = 0; a < dim; ++a) p[a] = get_index_number(L, t, fn, a + 1, key);
  }
  lua_pop(L, 1);
  return present;
}

/* t[key] as one of `names` (NULL-terminated); returns its index, or def when absent. */
static int get_choice(lua_State *L, int idx, const char *fn, const char *key,
                      const char *const *names, int def)
{
  char hint[256];
  int r = def;
  lua_getfield(L, idx, key);
  if (!lua_isnil(L, -1)) {
    if (lua_type(L, -1) != LUA_TSTRING) luaL_error(L, "%s: '%s' must be a name", fn, key);
    const char *v = lua_tostring(L, -1);
    r = -1;
    for (int i = 0; names[i] != NULL; ++i)
      if (strcmp(v, names[i]) == 0) r = i;
    if (r < 0) {
      spell_suggest(v, names, hint, sizeof hint);
      luaL_error(L, "%s: '%s' is not a valid %s%s", fn, v, key, hint);
    }
  }
  lua_pop(L, 1);
  return r;
}

static void get_name(lua_State *L, int idx, const char *fn, const char *key, char *out,
                     const char *def)
{
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) {
    snprintf(out, SCENE_NAME, "%s", def);
  } else {
    if (lua_type(L, -1) != LUA_TSTRING) luaL_error(L, "%s: '%s' must be a string", fn, key);
    size_t len = 0;
    const char *v = lua_tolstring(L, -1, &len);
    if (len == 0 || len >= SCENE_NAME)
      luaL_error(L, "%s: '%s' must have 1 to %d characters", fn, key, SCENE_NAME - 1);
    snprintf(out, SCENE_NAME, "%s", v);
  }
  lua_pop(L, 1);
}

/* Grow an array of `size`-byte items by one; the new item is zeroed. */
static void *grow(lua_State *L, void **arr, int *count, size_t size)
{
  char *p = realloc(*arr, (size_t)(*count + 1) * size);
  if (p == NULL) luaL_error(L, "out of memory");
  memset(p + (size_t)*count * size, 0, size);
  *arr = p;
  return p + (size_t)(*count)++ * size;
}

static void once(lua_State *L, int *line, const char *fn)
{
  if (*line != 0) luaL_error(L, "%s: declared twice (first on line %d)", fn, *line);
  *line = current_line(L);
}

static void need_table(lua_State *L, const char *fn)
{
  if (lua_gettop(L) != 1 || !lua_istable(L, 1))
    luaL_error(L, "%s: expects one table, e.g. %s { ... }", fn, fn);
}

static int l_reference(lua_State *L); /* reference(csv, column...): the same at load time */

/* ---- declarations ---- */

static int l_param(lua_State *L)
{
  struct loader *ld = loader_of(L);
  struct scene *s = ld->s;
  need_table(L, "param");
  lua_pushnil(L);
  while (lua_next(L, 1) != 0) {
    if (lua_type(L, -2) != LUA_TSTRING) luaL_error(L, "param: names must be strings");
    const char *name = lua_tostring(L, -2);
    if (!lua_isnumber(L, -1)) luaL_error(L, "param: '%s' must have a number as default", name);
    if (strlen(name) >= SCENE_NAME) luaL_error(L, "param: name '%s' is too long", name);
    for (int i = 0; i < s->nparams; ++i)
      if (strcmp(s->params[i].name, name) == 0) luaL_error(L, "param: '%s' declared twice", name);
    struct scene_param *p = grow(L, (void **)&s->params, &s->nparams, sizeof *p);
    snprintf(p->name, SCENE_NAME, "%s", name);
    p->value = lua_tonumber(L, -1);
    for (int k = 0; k < ld->nsets; ++k) {
      if (strcmp(ld->set_names[k], name) == 0) {
        p->value = ld->set_values[k];
        p->overridden = 1;
        ld->set_used[k] = 1;
      }
    }
    lua_pushnumber(L, p->value); /* the script sees the value in force */
    lua_setglobal(L, name);
    lua_pop(L, 1);
  }
  return 0;
}

static int l_domain(lua_State *L)
{
  static const char *const keys[] = {"periodic", NULL};
  static const char *const periodic[] = {"none", "x", "y", "xy", "z", "xz", "yz", "xyz", NULL};
  struct loader *ld = loader_of(L);
  need_table(L, "domain");
  once(L, &ld->line_domain, "domain");
  check_keys(L, 1, "domain", keys, 1);
  const lua_Unsigned len = lua_rawlen(L, 1);
  if (len != 4 && len != 6)
    luaL_error(L,
               "domain: give the box as { x0, y0, x1, y1 } (2-D) or { x0, y0, z0, x1, y1, z1 } "
               "(3-D), not %d numbers",
               (int)len);
  struct scene *s = ld->s;
  const int dim = len == 6 ? 3 : 2;
  static const char *const names[2][6] = {{"x0", "y0", "x1", "y1"},
                                          {"x0", "y0", "z0", "x1", "y1", "z1"}};
  for (int a = 0; a < dim; ++a) {
    s->lo[a] = get_index_number(L, 1, "domain", a + 1, names[dim - 2][a]);
    s->hi[a] = get_index_number(L, 1, "domain", dim + a + 1, names[dim - 2][dim + a]);
    if (!(s->hi[a] > s->lo[a]))
      luaL_error(L, "domain: the box is empty along %c: %s = %f must exceed %s = %f", "xyz"[a],
                 names[dim - 2][dim + a], s -> hi[a], names[dim - 2][a], s -> lo[a]);
  }
  s->dim = dim;
  int p = get_choice(L, 1, "domain", "periodic", periodic, 0);
  if (dim == 2 && p > 3) luaL_error(L, "domain: periodic along z needs a 3-D domain (6 numbers)");
  s->periodic[0] = p & 1;
  s->periodic[1] = (p >> 1) & 1;
  s->periodic[2] = (p >> 2) & 1;
  return 0;
}

static int l_particles(lua_State *L)
{
  static const char *const keys[] = {"dr", "h_over_dr", "smoothing", NULL};
  static const char *const kinds[] = {"wendland", "cubic_spline", "gaussian", NULL};
  struct loader *ld = loader_of(L);
  need_table(L, "particles");
  once(L, &ld->line_particles, "particles");
  check_keys(L, 1, "particles", keys, 0);
  struct scene *s = ld->s;
  s->dr = get_number(L, 1, "particles", "dr", NAN);
  if (!(s->dr > 0.0)) luaL_error(L, "particles: dr must be a positive spacing, not %f", s->dr);
  s->h_over_dr = get_number(L, 1, "particles", "h_over_dr", NAN); /* absent: the scheme's */
  if (!isnan(s->h_over_dr) && !(s->h_over_dr > 0.0 && s->h_over_dr <= 10.0))
    luaL_error(L, "particles: h_over_dr must be in (0, 10], not %f", s->h_over_dr);
  if (isnan(s->h_over_dr)) s->h_over_dr = 0.0;
  int k = get_choice(L, 1, "particles", "smoothing", kinds, -1);
  if (k >= 0) snprintf(s->smoothing, SCENE_NAME, "%s", kinds[k]);
  return 0;
}

static void scheme_name(lua_State *L, const char *name, struct scene *s)
{
  if (name[0] == '\0' || strlen(name) >= SCENE_NAME)
    luaL_error(L, "scheme: '%s' is not a scheme name (1 to %d characters)", name, SCENE_NAME - 1);
  snprintf(s->scheme, SCENE_NAME, "%s", name);
}

static int l_scheme(lua_State *L)
{
  struct loader *ld = loader_of(L);
  struct scene *s = ld->s;
  once(L, &ld->line_scheme, "scheme");
  s->scheme_line = ld->line_scheme;
  if (lua_gettop(L) == 1 && lua_type(L, 1) == LUA_TSTRING) {
    scheme_name(L, lua_tostring(L, 1), s);
    return 0;
  }
  need_table(L, "scheme");
  lua_geti(L, 1, 1);
  if (lua_type(L, -1) != LUA_TSTRING)
    luaL_error(L, "scheme: name the scheme first: scheme { \"name\", ... }");
  scheme_name(L, lua_tostring(L, -1), s);
  lua_pop(L, 1);
  lua_pushnil(L);
  while (lua_next(L, 1) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING) {
      struct scene_option *o = grow(L, (void **)&s->options, &s->noptions, sizeof *o);
      snprintf(o->key, SCENE_NAME, "%s", lua_tostring(L, -2));
      if (lua_type(L, -1) == LUA_TNUMBER) {
        o->is_number = 1;
        o->number = lua_tonumber(L, -1);
      } else if (lua_type(L, -1) == LUA_TSTRING) {
        snprintf(o->text, SCENE_NAME, "%s", lua_tostring(L, -1));
      } else if (lua_type(L, -1) == LUA_TBOOLEAN) {
        o->is_number = 1;
        o->number = lua_toboolean(L, -1);
      } else {
        luaL_error(L, "scheme: option '%s' must be a number, a name or a boolean", o->key);
      }
    } else if (!lua_isinteger(L, -2) || lua_tointeger(L, -2) != 1) {
      luaL_error(L, "scheme: give options as name = value");
    }
    lua_pop(L, 1);
  }
  return 0;
}

/* fluid { flow_rate_control = { velocity = U, slice = {x0, x1} } } (eqs 67-68) */
static void flow_rate_control(lua_State *L, int idx, struct scene *s)
{
  static const char *const keys[] = {"velocity", "slice", NULL};
  const char *fn = "fluid: flow_rate_control";
  struct scene_flow_control *c = &s->flow;
  if (!lua_istable(L, idx))
    luaL_error(L, "%s: expects a table { velocity = U, slice = {x0, x1} }", fn);
  check_keys(L, idx, fn, keys, 0);
  c->velocity = get_number(L, idx, fn, "velocity", NAN);
  if (isnan(c->velocity)) luaL_error(L, "%s: needs velocity = (m/s), the target mean velocity", fn);
  lua_getfield(L, idx, "slice");
  if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 2)
    luaL_error(L, "%s: needs slice = {x0, x1}, the x range where the velocity is measured", fn);
  for (int k = 0; k < 2; ++k) c->slice[k] = get_index_number(L, lua_gettop(L), fn, k + 1, "slice");
  lua_pop(L, 1);
  if (!(c->slice[1] > c->slice[0]))
    luaL_error(L, "%s: the slice {%f, %f} is empty (x1 > x0 needed)", fn, c->slice[0], c->slice[1]);
  c->on = 1;
  c->line = current_line(L);
}

static int l_fluid(lua_State *L)
{
  static const char *const keys[] = {"density",    "viscosity",         "gravity",
                                     "body_force", "flow_rate_control", NULL};
  struct loader *ld = loader_of(L);
  need_table(L, "fluid");
  once(L, &ld->line_fluid, "fluid");
  check_keys(L, 1, "fluid", keys, 0);
  struct scene *s = ld->s;
  s->rho0 = get_number(L, 1, "fluid", "density", 1000.0);
  s->nu = get_number(L, 1, "fluid", "viscosity", 0.0);
  if (!(s->rho0 > 0.0)) luaL_error(L, "fluid: density must be positive, not %f", s->rho0);
  if (s->nu < 0.0) luaL_error(L, "fluid: viscosity must not be negative, not %f", s->nu);
  get_vector(L, 1, "fluid", "gravity", s->gravity);
  get_vector(L, 1, "fluid", "body_force", s->body_force);
  lua_getfield(L, 1, "flow_rate_control");
  if (!lua_isnil(L, -1)) flow_rate_control(L, lua_gettop(L), s);
  lua_pop(L, 1);
  return 0;
}

/* turbulence { model = "k-epsilon", k = K, epsilon = E, y_p = Y, delay = T, nu_t = N,
 * wall_weight = W, wall_law = "two-layer" | "scalable", production = "semi-linear" | "standard" }:
 * which model, its initial (and entry) k and ε, the wall model's distance (wcsph-riemann), the
 * wall law and the production of k (the USAW schemes); the values'
 * consistency is checked in finish(), once the fluid and the particles are known */
static int l_turbulence(lua_State *L)
{
  static const char *const keys[] = {"model", "k",           "epsilon",  "y_p",        "delay",
                                     "nu_t",  "wall_weight", "wall_law", "production", NULL};
  static const char *const models[] = {"k-epsilon", NULL};
  static const char *const laws[] = {"two-layer", "scalable", NULL};
  static const char *const productions[] = {"semi-linear", "standard", NULL};
  struct loader *ld = loader_of(L);
  struct scene_turbulence *t = &ld->s->turb;
  need_table(L, "turbulence");
  if (t->on) luaL_error(L, "turbulence: declared twice (first on line %d)", t->line);
  check_keys(L, 1, "turbulence", keys, 0);
  lua_getfield(L, 1, "model");
  if (lua_isnil(L, -1)) luaL_error(L, "turbulence: needs model = \"k-epsilon\"");
  lua_pop(L, 1);
  int m = get_choice(L, 1, "turbulence", "model", models, 0);
  snprintf(t->model, SCENE_NAME, "%s", models[m]);
  t->k = get_number(L, 1, "turbulence", "k", NAN);
  t->epsilon = get_number(L, 1, "turbulence", "epsilon", NAN);
  t->y_p = get_number(L, 1, "turbulence", "y_p", 0.0);
  t->delay = get_number(L, 1, "turbulence", "delay", 0.0);
  t->nu_t_delay = get_number(L, 1, "turbulence", "nu_t", NAN);
  t->wall_weight = get_number(L, 1, "turbulence", "wall_weight", NAN);
  t->wall_law = get_choice(L, 1, "turbulence", "wall_law", laws, -1);
  t->production = get_choice(L, 1, "turbulence", "production", productions, -1);
  if (isnan(t->k) || isnan(t->epsilon))
    luaL_error(L,
               "turbulence: needs both k (m²/s²) and epsilon (m²/s³), the initial and entry "
               "values: %s is missing",
               isnan(t->k) ? "k" : "epsilon");
  if (!(t->k > 0.0)) luaL_error(L, "turbulence: k must be positive, not %f", t->k);
  if (!(t->epsilon > 0.0))
    luaL_error(L, "turbulence: epsilon must be positive, not %f", t->epsilon);
  if (t->y_p < 0.0) luaL_error(L, "turbulence: y_p must be a positive distance, not %f", t->y_p);
  if (t->delay < 0.0) luaL_error(L, "turbulence: delay must not be negative, not %f", t->delay);
  if (t->delay > 0.0 && !(t->nu_t_delay > 0.0))
    luaL_error(L, "turbulence: a delay needs nu_t > 0 (m²/s), the eddy viscosity until then");
  if (t->delay == 0.0 && !isnan(t->nu_t_delay))
    luaL_error(L, "turbulence: nu_t is the eddy viscosity of the delay: give delay = (s) too");
  if (!isnan(t->wall_weight) && !(t->wall_weight >= 0.0 && t->wall_weight <= 1.0))
    luaL_error(L, "turbulence: wall_weight (w_s of eq 40) must lie in [0, 1], not %f",
               t->wall_weight);
  t->on = 1;
  t->line = current_line(L);
  return 0;
}

static int l_fill(lua_State *L)
{
  static const char *const keys[] = {"polygon",  "points",   "name", "velocity",
                                     "pressure", "density",  "k",    "epsilon",
                                     "sphere",   "cylinder", NULL};
  struct loader *ld = loader_of(L);
  struct scene *s = ld->s;
  need_table(L, "fill");
  check_keys(L, 1, "fill", keys, 1);
  char defname[SCENE_NAME];
  snprintf(defname, sizeof defname, "fill %d", ++ld->nfill);
  struct scene_region *r = grow(L, (void **)&s->regions, &s->nregions, sizeof *r);
  r->line = current_line(L);
  get_name(L, 1, "fill", "name", r->name, defname);
  /* the initial velocity: {u, v}, or a function (x, y) -> u, v kept in the registry table
   * FILL_VELOCITY at the region's index, called when the particles are made */
  lua_getfield(L, 1, "velocity");
  if (lua_isfunction(L, -1)) {
    r->velocity = 2;
    if (lua_getfield(L, LUA_REGISTRYINDEX, FILL_VELOCITY) != LUA_TTABLE) {
      lua_pop(L, 1);
      lua_newtable(L);
      lua_pushvalue(L, -1);
      lua_setfield(L, LUA_REGISTRYINDEX, FILL_VELOCITY);
    }
    lua_pushvalue(L, -2);
    lua_rawseti(L, -2, s->nregions);
    lua_pop(L, 1);
  } else if (!lua_isnil(L, -1)) {
    if (s->dim == 3 && (!lua_istable(L, -1) || lua_rawlen(L, -1) != 3))
      luaL_error(L,
                 "fill '%s': velocity must be {u, v, w} (m/s) or a function (x, y, z) returning "
                 "u, v, w in a 3-D scene",
                 r->name);
    if (s->dim == 2 && (!lua_istable(L, -1) || lua_rawlen(L, -1) != 2))
      luaL_error(L, "fill '%s': velocity must be {u, v} (m/s) or a function (x, y) returning u, v",
                 r->name);
    r->velocity = 1;
    for (int a = 0; a < s->dim; ++a) r->u0[a] = get_index_number(L, -1, "fill", a + 1, "velocity");
  }
  lua_pop(L, 1);
  /* the initial pressure, density, k and ε: a number, or a function (x, y) -> value kept like
   * the velocity's */
  static const char *const unit[4] = {"Pa", "kg/m^3", "m²/s²", "m²/s³"};
  int *modes[4] = {&r->pressure, &r->density, &r->k, &r->epsilon};
  double *values[4] = {&r->p0, &r->rho0, &r->k0, &r->eps0};
  for (int k = 0; k < 4; ++k) {
    int *mode = modes[k];
    double *value = values[k];
    const char *const *scalar_key = fill_scalar_key, *const *scalar_reg = fill_scalar_reg;
    lua_getfield(L, 1, scalar_key[k]);
    if (lua_isfunction(L, -1)) {
      *mode = 2;
      if (lua_getfield(L, LUA_REGISTRYINDEX, scalar_reg[k]) != LUA_TTABLE) {
        lua_pop(L, 1);
        lua_newtable(L);
        lua_pushvalue(L, -1);
        lua_setfield(L, LUA_REGISTRYINDEX, scalar_reg[k]);
      }
      lua_pushvalue(L, -2);
      lua_rawseti(L, -2, s->nregions);
      lua_pop(L, 1);
    } else if (!lua_isnil(L, -1)) {
      if (lua_type(L, -1) != LUA_TNUMBER || !isfinite(lua_tonumber(L, -1)))
        luaL_error(L, "fill '%s': %s must be a number (%s) or a function (x, y) returning one",
                   r->name, scalar_key[k], unit[k]);
      *mode = 1;
      *value = lua_tonumber(L, -1);
      if (k >= 1 && !(*value > 0.0))
        luaL_error(L, "fill '%s': %s must be positive, not %f", r->name, scalar_key[k], *value);
    }
    lua_pop(L, 1);
  }
  /* points = { {x, y}, ... }: the particles' own positions (a body-fitted arrangement the
   * script computes), instead of the lattice inside a polygon or rectangle */
  const int sphere = lua_getfield(L, 1, "sphere") != LUA_TNIL;
  const int cylinder = lua_getfield(L, 1, "cylinder") != LUA_TNIL;
  lua_pop(L, 2);
  if ((sphere || cylinder) && s->dim != 3)
    luaL_error(L, "fill '%s': a %s is 3-D (declare the domain { x0, y0, z0, x1, y1, z1 } first)",
               r->name, sphere ? "sphere" : "cylinder");
  if (s->dim == 3) { /* a box { x0, y0, z0, x1, y1, z1 }, sphere = { ... } or cylinder = { ... } */
    lua_getfield(L, 1, "points");
    lua_getfield(L, 1, "polygon");
    if (!lua_isnil(L, -1) || !lua_isnil(L, -2))
      luaL_error(L,
                 "fill '%s': points and polygon are 2-D; a 3-D scene fills boxes { x0, y0, z0, "
                 "x1, y1, z1 }, sphere = { cx, cy, cz, R } or cylinder = { x0, y0, z0, x1, y1, "
                 "z1, R }",
                 r->name);
    lua_pop(L, 2);
    if (sphere || cylinder) {
      if (sphere && cylinder)
        luaL_error(L, "fill '%s': give a sphere or a cylinder, not both", r->name);
      if (lua_rawlen(L, 1) != 0)
        luaL_error(L, "fill '%s': a box's numbers and a %s: give one solid", r->name,
                   sphere ? "sphere" : "cylinder");
      char fn[SCENE_NAME + 16];
      snprintf(fn, sizeof fn, "fill '%s'", r->name);
      r->shape = sphere ? SCENE_SPHERE : SCENE_CYLINDER;
      lua_getfield(L, 1, sphere ? "sphere" : "cylinder");
      get_shape3(L, lua_gettop(L), fn, r->shape, r->shape3, r->box3);
      lua_pop(L, 1);
      return 0;
    }
    if (lua_rawlen(L, 1) != 6)
      luaL_error(L, "fill '%s': a 3-D scene fills a box { x0, y0, z0, x1, y1, z1 }", r->name);
    static const char *const bn[6] = {"x0", "y0", "z0", "x1", "y1", "z1"};
    for (int k = 0; k < 6; ++k) r->box3[k] = get_index_number(L, 1, "fill", k + 1, bn[k]);
    for (int a = 0; a < 3; ++a)
      if (!(r->box3[3 + a] > r->box3[a]))
        luaL_error(L, "fill '%s': the box is empty along %c (%s = %f, %s = %f)", r->name, "xyz"[a],
                   bn[a], r -> box3[a], bn[3 + a], r -> box3[3 + a]);
    return 0;
  }
  lua_getfield(L, 1, "points");
  if (!lua_isnil(L, -1)) {
    int t = lua_gettop(L);
    lua_getfield(L, 1, "polygon");
    const int polygon = !lua_isnil(L, -1);
    lua_pop(L, 1);
    if (polygon || lua_rawlen(L, 1) != 0)
      luaL_error(L, "fill '%s': give points, a polygon or a rectangle, not two of them", r->name);
    if (!lua_istable(L, t) || lua_rawlen(L, t) < 1)
      luaL_error(L, "fill '%s': points must be a list of particle positions { {x, y}, ... }",
                 r->name);
    const lua_Unsigned n = lua_rawlen(L, t);
    if (n > 100000000u)
      luaL_error(L, "fill '%s': %llu points: more than 1e8", r->name, (unsigned long long)n);
    r->pts = calloc(2 * (size_t)n, sizeof *r->pts);
    if (r->pts == NULL) luaL_error(L, "out of memory");
    r->npts = (int)n;
    r->given = 1;
    for (int i = 0; i < r->npts; ++i) {
      lua_geti(L, t, i + 1);
      const int ok = lua_istable(L, -1) && lua_rawlen(L, -1) == 2;
      if (ok) {
        lua_geti(L, -1, 1);
        lua_geti(L, -2, 2);
      }
      if (!ok || !lua_isnumber(L, -2) || !lua_isnumber(L, -1) || !isfinite(lua_tonumber(L, -2)) ||
          !isfinite(lua_tonumber(L, -1)))
        luaL_error(L, "fill '%s': points[%d] must be a point {x, y} of finite numbers", r->name,
                   i + 1);
      r->pts[2 * i] = lua_tonumber(L, -2);
      r->pts[2 * i + 1] = lua_tonumber(L, -1);
      lua_pop(L, 3);
    }
    lua_pop(L, 1);
    return 0;
  }
  lua_pop(L, 1);
  lua_getfield(L, 1, "polygon");
  if (!lua_isnil(L, -1)) {
    int t = lua_gettop(L);
    if (!lua_istable(L, t) || lua_rawlen(L, t) < 3)
      luaL_error(L, "fill: polygon needs at least 3 points {x, y}");
    if (lua_rawlen(L, 1) != 0) luaL_error(L, "fill: give either a rectangle or a polygon");
    int n = (int)lua_rawlen(L, t);
    r->pts = calloc(2 * (size_t)n, sizeof *r->pts);
    if (r->pts == NULL) luaL_error(L, "out of memory");
    r->npts = n;
    for (int i = 0; i < n; ++i) {
      lua_geti(L, t, i + 1);
      to_point(L, "fill", "a polygon point", &r->pts[2 * i]);
      lua_pop(L, 1);
    }
  } else {
    if (lua_rawlen(L, 1) != 4)
      luaL_error(L, "fill: give a rectangle { x0, y0, x1, y1 } or polygon = { {x, y}, ... }");
    double x0 = get_index_number(L, 1, "fill", 1, "x0"),
           y0 = get_index_number(L, 1, "fill", 2, "y0");
    double x1 = get_index_number(L, 1, "fill", 3, "x1"),
           y1 = get_index_number(L, 1, "fill", 4, "y1");
    if (!(x1 > x0 && y1 > y0))
      luaL_error(L, "fill: the rectangle {%f, %f, %f, %f} is empty", x0, y0, x1, y1);
    r->pts = calloc(8, sizeof *r->pts);
    if (r->pts == NULL) luaL_error(L, "out of memory");
    r->npts = 4;
    const double q[8] = {x0, y0, x1, y0, x1, y1, x0, y1};
    memcpy(r->pts, q, sizeof q);
  }
  lua_pop(L, 1);
  return 0;
}

/* Signed area (positive when counter-clockwise). */
static double signed_area(const double *p, int n)
{
  double a = 0.0;
  for (int i = 0; i < n; ++i) {
    int j = (i + 1) % n;
    a += p[2 * i] * p[2 * j + 1] - p[2 * j] * p[2 * i + 1];
  }
  return 0.5 * a;
}

static void reverse_points(double *p, int n)
{
  for (int i = 0; i < n / 2; ++i) {
    for (int c = 0; c < 2; ++c) {
      double t = p[2 * i + c];
      p[2 * i + c] = p[2 * (n - 1 - i) + c];
      p[2 * (n - 1 - i) + c] = t;
    }
  }
}

/* (b − a) × (c − a): > 0 when c is left of a → b. */
static double orient2(const double *a, const double *b, const double *c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Is c, collinear with a → b, within its bounding box? */
static int within(const double *a, const double *b, const double *c)
{
  return fmin(a[0], b[0]) <= c[0] && c[0] <= fmax(a[0], b[0]) && fmin(a[1], b[1]) <= c[1] &&
         c[1] <= fmax(a[1], b[1]);
}

/* Do the segments a → b and c → d share a point (crossing, touching or overlapping)? */
static int segments_meet(const double *a, const double *b, const double *c, const double *d)
{
  const double d1 = orient2(c, d, a), d2 = orient2(c, d, b);
  const double d3 = orient2(a, b, c), d4 = orient2(a, b, d);
  if (((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) &&
      ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)))
    return 1;
  return (d1 == 0.0 && within(c, d, a)) || (d2 == 0.0 && within(c, d, b)) ||
         (d3 == 0.0 && within(a, b, c)) || (d4 == 0.0 && within(a, b, d));
}

/* A wall polyline must not cross or touch itself (but at the vertex two neighbouring segments
 * share): its fluid side would change along it, and a closed one would enclose no single
 * region. */
static void check_simple(lua_State *L, const char *fn, const struct scene_wall *w)
{
  const int nseg = w->closed ? w->npts : w->npts - 1;
  for (int i = 0; i < nseg; ++i) {
    const double *a = &w->pts[2 * i], *b = &w->pts[2 * ((i + 1) % w->npts)];
    /* the next segment may not turn straight back along this one */
    if (i + 1 < nseg || w->closed) {
      const double *d = &w->pts[2 * ((i + 2) % w->npts)];
      if (orient2(a, b, d) == 0.0 &&
          (b[0] - a[0]) * (d[0] - b[0]) + (b[1] - a[1]) * (d[1] - b[1]) < 0.0)
        luaL_error(L, "%s: the polyline turns back on itself at its point %d, (%f, %f)", fn,
                   (i + 1) % w->npts + 1, b[0], b[1]);
    }
    for (int j = i + 2; j < nseg; ++j) {
      if (i == 0 && j == nseg - 1 &&
          (w->closed ||
           (w->pts[0] == w->pts[2 * w->npts - 2] && w->pts[1] == w->pts[2 * w->npts - 1])))
        continue; /* they share the first point (a closed wall, or one drawn back to its start) */
      const double *c = &w->pts[2 * j], *d = &w->pts[2 * ((j + 1) % w->npts)];
      if (segments_meet(a, b, c, d))
        luaL_error(L,
                   "%s: the polyline crosses itself: its segment %d, (%f, %f) to (%f, %f), meets "
                   "its segment %d, (%f, %f) to (%f, %f)",
                   fn, i + 1, a[0], a[1], b[0], b[1], j + 1, c[0], c[1], d[0], d[1]);
    }
  }
}

/* Motion keys shared by every wall declaration. */
static void wall_motion(lua_State *L, const char *fn, struct scene_wall *w)
{
  int has_v = get_point(L, 1, fn, "velocity", w->velocity);
  lua_getfield(L, 1, "omega");
  int has_w = !lua_isnil(L, -1);
  lua_pop(L, 1);
  if (has_v && has_w) luaL_error(L, "%s: give either velocity (sliding) or omega (rotating)", fn);
  if (has_w) {
    w->omega = get_number(L, 1, fn, "omega", 0.0);
    if (!get_point(L, 1, fn, "centre", w->centre))
      luaL_error(L, "%s: a rotating wall (omega) needs its centre = {x, y}", fn);
    w->motion = SCENE_ROTATING;
  } else if (has_v) {
    w->motion = SCENE_SLIDING;
  }
}

/* Orient a wall so that the fluid is on its left (see scene.h). */
static void orient(lua_State *L, const char *fn, struct scene_wall *w, int fluid_choice)
{
  /* choices: 0 default, 1 inside, 2 outside, 3 left, 4 right */
  if (w->closed) {
    if (fluid_choice >= 3) luaL_error(L, "%s: a closed wall holds the fluid inside or outside", fn);
    double a = signed_area(w->pts, w->npts);
    if (fabs(a) == 0.0) luaL_error(L, "%s: the closed wall encloses no area", fn);
    int want_ccw = fluid_choice != 2;
    if ((a > 0.0) != want_ccw) reverse_points(w->pts, w->npts);
  } else {
    if (fluid_choice == 1 || fluid_choice == 2)
      luaL_error(L, "%s: an open wall has its fluid on the left or the right", fn);
    if (fluid_choice == 4) reverse_points(w->pts, w->npts);
  }
}

static const char *const fluid_sides[] = {"", "inside", "outside", "left", "right", NULL};
/* wall { dummies = ... }: the dummy layers on the lattice, or in rows along the wall */
static const char *const arrangements[] = {"lattice", "fitted", NULL};

static int l_wall(lua_State *L)
{
  static const char *const keys[] = {"closed", "fluid",  "group",   "velocity",
                                     "omega",  "centre", "dummies", NULL};
  struct loader *ld = loader_of(L);
  struct scene *s = ld->s;
  need_table(L, "wall");
  check_keys(L, 1, "wall", keys, 1);
  int n = (int)lua_rawlen(L, 1);
  if (n < 2) luaL_error(L, "wall: a polyline needs at least 2 points {x, y}, this one has %d", n);
  struct scene_wall *w = grow(L, (void **)&s->walls, &s->nwalls, sizeof *w);
  w->line = current_line(L);
  get_name(L, 1, "wall", "group", w->group, "walls");
  lua_getfield(L, 1, "closed");
  w->closed = lua_toboolean(L, -1);
  lua_pop(L, 1);
  if (w->closed && n < 3) luaL_error(L, "wall: a closed wall needs at least 3 points");
  w->pts = calloc(2 * (size_t)n, sizeof *w->pts);
  if (w->pts == NULL) luaL_error(L, "out of memory");
  w->npts = n;
  for (int i = 0; i < n; ++i) {
    lua_geti(L, 1, i + 1);
    to_point(L, "wall", "a point", &w->pts[2 * i]);
    lua_pop(L, 1);
  }
  w->fitted = get_choice(L, 1, "wall", "dummies", arrangements, 0) == 1;
  wall_motion(L, "wall", w);
  check_simple(L, "wall", w);
  orient(L, "wall", w, get_choice(L, 1, "wall", "fluid", fluid_sides, 0));
  return 0;
}

/* sphere_wall { cx, cy, cz, R, ... } and cylinder_wall { x0, y0, z0, x1, y1, z1, R, ... }: a
 * closed 3-D solid, the fluid inside (a container: fluid = "inside", the default) or outside (an
 * obstacle) */
static int shape_wall(lua_State *L, enum scene_shape3 kind)
{
  static const char *const keys[] = {"group", "fluid", NULL};
  static const char *const sides[] = {"inside", "outside", NULL};
  const char *fn = kind == SCENE_SPHERE ? "sphere_wall" : "cylinder_wall";
  struct scene *s = loader_of(L)->s;
  need_table(L, fn);
  check_keys(L, 1, fn, keys, 1);
  if (s->dim != 3)
    luaL_error(L, "%s is 3-D: declare the domain { x0, y0, z0, x1, y1, z1 } first%s", fn,
               kind == SCENE_SPHERE ? " (a 2-D circle is circle { })" : "");
  const int side = get_choice(L, 1, fn, "fluid", sides, 0);
  struct scene_wall *w = grow(L, (void **)&s->walls, &s->nwalls, sizeof *w);
  w->line = current_line(L);
  get_name(L, 1, fn, "group", w->group, "walls");
  w->box3d = side == 1 ? 2 : 1;
  w->closed = 1;
  w->shape = kind;
  get_shape3(L, 1, fn, kind, w->shape3, w->box3);
  return 0;
}

/* stl_wall { "file.stl", fluid = "inside" | "outside", group =, scale = 1, offset = {x, y, z} }:
 * the solid a closed STL surface bounds (read and checked in finish: mesh.c), the fluid inside it
 * (the default, as a box_wall's) or outside (an obstacle); the file's path is relative to the
 * case script's folder unless absolute */
static int l_stl_wall(lua_State *L)
{
  static const char *const keys[] = {"group", "fluid", "scale", "offset", NULL};
  static const char *const sides[] = {"inside", "outside", NULL};
  struct scene *s = loader_of(L)->s;
  need_table(L, "stl_wall");
  check_keys(L, 1, "stl_wall", keys, 1);
  if (s->dim != 3)
    luaL_error(L, "stl_wall is 3-D: declare the domain { x0, y0, z0, x1, y1, z1 } first");
  if (lua_rawlen(L, 1) != 1 || lua_rawgeti(L, 1, 1) != LUA_TSTRING)
    luaL_error(L, "stl_wall: give the file as its first entry, stl_wall { \"body.stl\", ... }");
  const char *file = lua_tostring(L, -1);
  const int side = get_choice(L, 1, "stl_wall", "fluid", sides, 0);
  const double scale = get_number(L, 1, "stl_wall", "scale", 1.0);
  if (!(scale > 0.0)) luaL_error(L, "stl_wall: scale must be positive, not %f", scale);
  double offset[3] = {0.0, 0.0, 0.0};
  get_vector(L, 1, "stl_wall", "offset", offset);
  struct scene_wall *w = grow(L, (void **)&s->walls, &s->nwalls, sizeof *w);
  w->line = current_line(L);
  get_name(L, 1, "stl_wall", "group", w->group, "walls");
  w->box3d = side == 1 ? 2 : 1;
  w->closed = 1;
  w->shape = SCENE_MESH;
  w->stl_scale = scale;
  memcpy(w->stl_offset, offset, sizeof offset);
  /* beside the case script unless absolute */
  const char *slash = strrchr(s->case_path, '/');
  const int dirlen = file[0] == '/' || slash == NULL ? 0 : (int)(slash - s->case_path) + 1;
  const size_t size = (size_t)dirlen + strlen(file) + 1;
  w->stl = malloc(size);
  if (w->stl == NULL) luaL_error(L, "out of memory");
  snprintf(w->stl, size, "%.*s%s", dirlen, s->case_path, file);
  lua_pop(L, 1);
  return 0;
}

static int l_sphere_wall(lua_State *L)
{
  return shape_wall(L, SCENE_SPHERE);
}

static int l_cylinder_wall(lua_State *L)
{
  return shape_wall(L, SCENE_CYLINDER);
}

static int l_box_wall(lua_State *L)
{
  static const char *const keys[] = {"group",    "lid_velocity", "lid_group",
                                     "lid_face", "fluid",        NULL};
  static const char *const sides[] = {"inside", "outside", NULL};
  static const char *const faces[] = {"x0", "x1", "y0", "y1", "z0", "z1", NULL};
  struct loader *ld = loader_of(L);
  struct scene *s = ld->s;
  need_table(L, "box_wall");
  check_keys(L, 1, "box_wall", keys, 1);
  const int side = get_choice(L, 1, "box_wall", "fluid", sides, 0);
  if (s->dim == 3) { /* a closed box, the fluid inside (a tank) or outside (an obstacle) */
    if (lua_rawlen(L, 1) != 6)
      luaL_error(L, "box_wall: give the box as { x0, y0, z0, x1, y1, z1 } in a 3-D scene");
    /* a sliding face (the lid of a cavity): its dummies move at lid_velocity, along the face */
    double lid[3] = {0.0, 0.0, 0.0};
    const int has_lid = get_vector(L, 1, "box_wall", "lid_velocity", lid);
    const int face = get_choice(L, 1, "box_wall", "lid_face", faces, 5);
    lua_getfield(L, 1, "lid_group");
    if (!lua_isnil(L, -1))
      luaL_error(L, "box_wall: lid_group is 2-D (a 3-D lid's dummies stay in the box's group)");
    lua_getfield(L, 1, "lid_face");
    if (!lua_isnil(L, -1) && !has_lid) luaL_error(L, "box_wall: lid_face needs lid_velocity");
    lua_pop(L, 2);
    if (has_lid && side == 1)
      luaL_error(L, "box_wall: lid_velocity belongs to a container (fluid = \"inside\")");
    if (has_lid && lid[face / 2] != 0.0)
      luaL_error(L,
                 "box_wall: lid_velocity {%f, %f, %f} crosses the lid face %s: its %c component "
                 "must be 0 (the lid slides along its face)",
                 lid[0], lid[1], lid[2], faces[face], "xyz"[face / 2]);
    static const char *const bn[6] = {"x0", "y0", "z0", "x1", "y1", "z1"};
    struct scene_wall *w = grow(L, (void **)&s->walls, &s->nwalls, sizeof *w);
    w->line = current_line(L);
    get_name(L, 1, "box_wall", "group", w->group, "walls");
    w->box3d = side == 1 ? 2 : 1;
    w->closed = 1;
    if (has_lid) {
      w->lid3 = 1 + face;
      memcpy(w->velocity, lid, sizeof lid);
    }
    for (int k = 0; k < 6; ++k) w->box3[k] = get_index_number(L, 1, "box_wall", k + 1, bn[k]);
    for (int a = 0; a < 3; ++a)
      if (!(w->box3[3 + a] > w->box3[a]))
        luaL_error(L, "box_wall: the box is empty along %c (%s = %f, %s = %f)", "xyz"[a], bn[a],
                   w -> box3[a], bn[3 + a], w -> box3[3 + a]);
    return 0;
  }
  if (side != 0)
    luaL_error(L, "box_wall: fluid = \"outside\" makes a 3-D obstacle; a 2-D one is wall { ..., "
                  "closed = true, fluid = \"outside\" }");
  if (lua_rawlen(L, 1) != 4) luaL_error(L, "box_wall: give the box as { x0, y0, x1, y1 }");
  double x0 = get_index_number(L, 1, "box_wall", 1, "x0"),
         y0 = get_index_number(L, 1, "box_wall", 2, "y0");
  double x1 = get_index_number(L, 1, "box_wall", 3, "x1"),
         y1 = get_index_number(L, 1, "box_wall", 4, "y1");
  if (!(x1 > x0 && y1 > y0))
    luaL_error(L, "box_wall: the box {%f, %f, %f, %f} is empty", x0, y0, x1, y1);
  double lid[2] = {0, 0};
  int has_lid = get_point(L, 1, "box_wall", "lid_velocity", lid);
  int line = current_line(L);
  struct scene_wall *w = grow(L, (void **)&s->walls, &s->nwalls, sizeof *w);
  w->line = line;
  get_name(L, 1, "box_wall", "group", w->group, "walls");
  if (!has_lid) { /* one closed counter-clockwise polyline: fluid inside */
    const double q[8] = {x0, y0, x1, y0, x1, y1, x0, y1};
    w->closed = 1;
    w->npts = 4;
    w->pts = malloc(sizeof q);
    if (w->pts == NULL) luaL_error(L, "out of memory");
    memcpy(w->pts, q, sizeof q);
    return 0;
  }
  /* left, bottom, right as one open polyline (fluid on its left), and the sliding lid */
  const double q[8] = {x0, y1, x0, y0, x1, y0, x1, y1};
  w->npts = 4;
  w->pts = malloc(sizeof q);
  if (w->pts == NULL) luaL_error(L, "out of memory");
  memcpy(w->pts, q, sizeof q);
  struct scene_wall *t = grow(L, (void **)&s->walls, &s->nwalls, sizeof *t);
  t->line = line;
  get_name(L, 1, "box_wall", "lid_group", t->group, "lid");
  t->npts = 2;
  t->pts = malloc(4 * sizeof *t->pts);
  if (t->pts == NULL) luaL_error(L, "out of memory");
  t->pts[0] = x1;
  t->pts[1] = y1;
  t->pts[2] = x0;
  t->pts[3] = y1;
  t->motion = SCENE_SLIDING;
  t->velocity[0] = lid[0];
  t->velocity[1] = lid[1];
  return 0;
}

/* arc and circle: a polyline with vertices about dr apart (particles {} must come first). */
static int arc_common(lua_State *L, int full)
{
  static const char *const arc_keys[] = {"centre", "radius",   "from",  "to",      "fluid",
                                         "group",  "velocity", "omega", "dummies", NULL};
  static const char *const circle_keys[] = {"centre",   "radius", "fluid",   "group",
                                            "velocity", "omega",  "dummies", NULL};
  const char *fn = full ? "circle" : "arc";
  struct loader *ld = loader_of(L);
  struct scene *s = ld->s;
  need_table(L, fn);
  check_keys(L, 1, fn, full ? circle_keys : arc_keys, 0);
  if (ld->line_particles == 0) luaL_error(L, "%s: declare particles { dr = ... } first", fn);
  double c[2];
  if (!get_point(L, 1, fn, "centre", c)) luaL_error(L, "%s: needs centre = {x, y}", fn);
  double r = get_number(L, 1, fn, "radius", NAN);
  if (!(r > 0.0)) luaL_error(L, "%s: radius must be positive, not %f", fn, r);
  double a0 = full ? 0.0 : get_number(L, 1, fn, "from", NAN);
  double a1 = full ? 2.0 * 3.14159265358979323846 : get_number(L, 1, fn, "to", NAN);
  if (!full && !(a1 > a0)) luaL_error(L, "arc: needs from < to (radians, counter-clockwise)");
  int side = get_choice(L, 1, fn, "fluid", fluid_sides, full ? 2 : 1);
  if (side != 1 && side != 2) luaL_error(L, "%s: fluid must be \"inside\" or \"outside\"", fn);
  if (!full && a1 - a0 > 2.0 * 3.14159265358979323846 * (1.0 + 1e-12))
    luaL_error(L, "arc: from %f to %f turns more than once around; a full turn is a circle", a0,
               a1);
  const double length = ceil(r * (a1 - a0) / s->dr);
  if (!(length <= 1e7))
    luaL_error(L, "%s: %.0f vertices about dr apart: more than 1e7 (radius %f at dr = %f)", fn,
               length, r, s->dr);
  int segs = (int)length;
  if (segs < (full ? 8 : 1)) segs = full ? 8 : 1;
  int n = full ? segs : segs + 1;
  struct scene_wall *w = grow(L, (void **)&s->walls, &s->nwalls, sizeof *w);
  w->line = current_line(L);
  get_name(L, 1, fn, "group", w->group, "walls");
  w->closed = full;
  w->npts = n;
  w->pts = calloc(2 * (size_t)n, sizeof *w->pts);
  if (w->pts == NULL) luaL_error(L, "out of memory");
  for (int i = 0; i < n; ++i) {
    double a = a0 + (a1 - a0) * i / segs;
    w->pts[2 * i] = c[0] + r * cos(a);
    w->pts[2 * i + 1] = c[1] + r * sin(a);
  }
  if (!full && side == 2) reverse_points(w->pts, n); /* counter-clockwise keeps the centre left */
  w->fitted = get_choice(L, 1, fn, "dummies", arrangements, 0) == 1;
  wall_motion(L, fn, w);
  if (full) orient(L, fn, w, side);
  return 0;
}

static int l_arc(lua_State *L)
{
  return arc_common(L, 0);
}

static int l_circle(lua_State *L)
{
  return arc_common(L, 1);
}

/* An entry's functions of s (fns[q] for velocity, k, epsilon: names[q]) sampled along it into
 * c->prof (INFLOW_SAMPLES points; NAN for the values given as numbers); the velocity's largest
 * |u| into c->velocity, its mean (trapezoidal) into c->mean. k and ε must be positive. */
#define INFLOW_SAMPLES 1025
static void inflow_table(lua_State *L, struct scene_section *c, const int fns[3],
                         const char *const names[3])
{
  static const char *const unit[3] = {"m/s", "m²/s²", "m²/s³"};
  const double len = hypot(c->b[0] - c->a[0], c->b[1] - c->a[1]);
  c->nprof = INFLOW_SAMPLES;
  c->prof = malloc(3 * (size_t)c->nprof * sizeof *c->prof);
  if (c->prof == NULL) luaL_error(L, "out of memory");
  double top = 0.0, sum = 0.0;
  for (int i = 0; i < c->nprof; ++i) {
    const double at = len * (double)i / (double)(c->nprof - 1);
    for (int q = 0; q < 3; ++q) {
      double v = NAN;
      if (fns[q]) {
        lua_getfield(L, 1, names[q]);
        lua_pushnumber(L, at);
        lua_call(L, 1, 1);
        if (lua_type(L, -1) != LUA_TNUMBER)
          luaL_error(L,
                     "inflow '%s': the %s function returned %s at s = %f: it must return a "
                     "number (%s)",
                     c->name, names[q], luaL_typename(L, -1), at, unit[q]);
        v = lua_tonumber(L, -1);
        lua_pop(L, 1);
        if (!isfinite(v) || (q > 0 && !(v > 0.0)))
          luaL_error(L, "inflow '%s': the %s function gives %f at s = %f: it must be %s (%s)",
                     c->name, names[q], v, at, q > 0 ? "positive" : "finite", unit[q]);
      }
      c->prof[3 * i + q] = v;
    }
    if (fns[0]) {
      const double u = c->prof[3 * i];
      top = fmax(top, fabs(u));
      sum += (i == 0 || i == c->nprof - 1) ? 0.5 * u : u;
    }
  }
  if (fns[0]) {
    c->velocity = top;
    c->mean = sum / (double)(c->nprof - 1);
    if (!(c->mean > 0.0))
      luaL_error(L,
                 "inflow '%s': the velocity function's mean over the section is %f m/s: an "
                 "entry's flow must go in (u > 0 along its normal)",
                 c->name, c->mean);
  }
}

static int section_common(lua_State *L, enum scene_section_kind kind)
{
  static const char *const in_keys[] = {"velocity", "profile", "layers",  "name",
                                        "ramp",     "k",       "epsilon", NULL};
  static const char *const out_keys[] = {"velocity", "profile", "layers", "name", "ramp", NULL};
  static const char *const profiles[] = {"", "uniform", "parabolic", NULL};
  static const char *const out_profiles[] = {"natural", "uniform", "parabolic", NULL};
  const char *fn = kind == SCENE_INFLOW ? "inflow" : "outflow";
  struct loader *ld = loader_of(L);
  struct scene *s = ld->s;
  need_table(L, fn);
  check_keys(L, 1, fn, kind == SCENE_INFLOW ? in_keys : out_keys, 1);
  if (lua_rawlen(L, 1) != 2)
    luaL_error(L, "%s: give the section as { {x0, y0}, {x1, y1}, ... }", fn);
  struct scene_section *c = grow(L, (void **)&s->sections, &s->nsections, sizeof *c);
  c->kind = kind;
  c->line = current_line(L);
  get_name(L, 1, fn, "name", c->name, fn);
  lua_geti(L, 1, 1);
  to_point(L, fn, "the first end", c->a);
  lua_pop(L, 1);
  lua_geti(L, 1, 2);
  to_point(L, fn, "the second end", c->b);
  lua_pop(L, 1);
  if (c->a[0] == c->b[0] && c->a[1] == c->b[1]) luaL_error(L, "%s: the section has no width", fn);
  const double layers = get_number(L, 1, fn, "layers", 3);
  if (!(layers >= 1 && layers <= 8 && layers == floor(layers)))
    luaL_error(L, "%s: layers must be a whole number from 1 to 8, not %f", fn, layers);
  c->layers = (int)layers;
  c->ramp = get_number(L, 1, fn, "ramp", 0.0);
  if (!(isfinite(c->ramp) && c->ramp >= 0.0))
    luaL_error(L,
               "%s: ramp must be a time of 0 s or more (the prescribed velocity rises over it), "
               "not %f",
               fn, c->ramp);
  if (kind == SCENE_INFLOW) {
    /* velocity, k and epsilon: numbers, or functions of s, the distance from the first end
     * along the section (a developed entry profile), sampled here */
    static const char *const tabulated[3] = {"velocity", "k", "epsilon"};
    int fns[3], any = 0;
    for (int q = 0; q < 3; ++q) {
      lua_getfield(L, 1, tabulated[q]);
      fns[q] = lua_isfunction(L, -1);
      any |= fns[q];
      lua_pop(L, 1);
    }
    if (any) inflow_table(L, c, fns, tabulated);
    if (fns[0]) {
      lua_getfield(L, 1, "profile");
      const int given = !lua_isnil(L, -1);
      lua_pop(L, 1);
      if (given)
        luaL_error(L,
                   "inflow '%s': profile = belongs to a velocity number; a velocity function "
                   "of s is its own profile",
                   c->name);
      if (c->ramp > 0.0)
        luaL_error(L,
                   "inflow '%s': ramp = %f needs a uniform or parabolic profile, not a velocity "
                   "function (start the fluid on the profile instead)",
                   c->name, c->ramp);
      c->profile = SCENE_TABLE;
    } else {
      c->velocity = get_number(L, 1, fn, "velocity", NAN);
      if (!isfinite(c->velocity)) luaL_error(L, "inflow: needs velocity = (m/s)");
      int p = get_choice(L, 1, fn, "profile", profiles, 1);
      c->profile = p == 2 ? SCENE_PARABOLIC : SCENE_UNIFORM;
    }
    /* the k-ε model's entry values (checked against turbulence { } at finish) */
    c->k = fns[1] ? (double)NAN : get_number(L, 1, fn, "k", NAN);
    c->epsilon = fns[2] ? (double)NAN : get_number(L, 1, fn, "epsilon", NAN);
    if (!isnan(c->k) && !(isfinite(c->k) && c->k > 0.0))
      luaL_error(L, "inflow '%s': k = %f must be a positive turbulent kinetic energy (m²/s²)",
                 c->name, c->k);
    if (!isnan(c->epsilon) && !(isfinite(c->epsilon) && c->epsilon > 0.0))
      luaL_error(L, "inflow '%s': epsilon = %f must be a positive dissipation rate (m²/s³)",
                 c->name, c->epsilon);
    const int has_k = fns[1] || !isnan(c->k), has_e = fns[2] || !isnan(c->epsilon);
    if (has_k != has_e)
      luaL_error(L,
                 "inflow '%s': give k and epsilon together (%s alone: the other would come from "
                 "turbulence { }, and the pair need not belong together)",
                 c->name, has_k ? "k" : "epsilon");
  } else {
    c->k = c->epsilon = NAN; /* natural exit (n·∇u = 0) unless a profile is prescribed */
    int p = get_choice(L, 1, fn, "profile", out_profiles, 0);
    c->profile = p == 2 ? SCENE_PARABOLIC : p == 1 ? SCENE_UNIFORM : 0;
    c->velocity = get_number(L, 1, fn, "velocity", NAN);
    if (c->profile != 0 && !(isfinite(c->velocity) && c->velocity > 0.0))
      luaL_error(L, "outflow: profile = \"%s\" needs velocity = (m/s, > 0: the %s speed out)",
                 out_profiles[p], p == 2 ? "peak" : "mean");
    if (c->profile == 0 && !isnan(c->velocity))
      luaL_error(L,
                 "outflow: velocity = %f needs a prescribed profile (\"parabolic\" or "
                 "\"uniform\"); a natural exit takes the velocity of the fluid",
                 c->velocity);
    if (c->profile == 0) c->velocity = 0.0;
    if (c->profile == 0 && c->ramp > 0.0)
      luaL_error(L,
                 "outflow: ramp = %f needs a prescribed profile: a natural exit takes the "
                 "velocity of the fluid",
                 c->ramp);
  }
  return 0;
}

static int l_inflow(lua_State *L)
{
  return section_common(L, SCENE_INFLOW);
}

static int l_outflow(lua_State *L)
{
  return section_common(L, SCENE_OUTFLOW);
}

/* probe { "name", {x, y} } or { name = ..., at = {x, y} }: a point;
 * probe { "name", {x0, y0}, {x1, y1}, points = N } or { name = ..., from = ..., to = ..., points =
 * N }: a face, the mean over the midpoints of N equal parts of it (N from dr unless given: at
 * finish, where dr is known). */
static int l_probe(lua_State *L)
{
  static const char *const keys[] = {"name",   "at",     "from",   "to",
                                     "points", "radius", "normal", NULL};
  struct loader *ld = loader_of(L);
  struct scene *s = ld->s;
  const char *forms = s->dim == 3
                          ? "a point, { \"name\", {x, y, z} }, a face, { \"name\", {x0, y0, z0}, "
                            "{x1, y1, z1} [, points = N] }, or a disc, { \"name\", {x, y, z}, "
                            "radius = R, normal = {nx, ny, nz} }"
                          : "a point, { \"name\", {x, y} }, or a face, { \"name\", {x0, y0}, "
                            "{x1, y1} [, points = N] }";
  need_table(L, "probe");
  check_keys(L, 1, "probe", keys, 1);
  struct scene_probe *p = grow(L, (void **)&s->probes, &s->nprobes, sizeof *p);
  p->line = current_line(L);
  lua_geti(L, 1, 1);
  const int named = lua_type(L, -1) == LUA_TSTRING;
  if (named) snprintf(p->name, SCENE_NAME, "%s", lua_tostring(L, -1));
  lua_pop(L, 1);
  if (!named) get_name(L, 1, "probe", "name", p->name, "");
  if (p->name[0] == '\0') luaL_error(L, "probe: it needs a name; give %s", forms);
  /* its points: after the name, or keyed (at = a point; from =, to = a face), not both */
  const int first = named ? 2 : 1, given = (int)lua_rawlen(L, 1) - first + 1;
  const int has_at = get_vec(L, 1, "probe", "at", p->x);
  const int has_from = get_vec(L, 1, "probe", "from", p->x);
  const int has_to = get_vec(L, 1, "probe", "to", p->b);
  if (given > 2) luaL_error(L, "probe '%s': %d points given; a probe is %s", p->name, given, forms);
  if (given > 0 && (has_at || has_from || has_to))
    luaL_error(L, "probe '%s': give its points after the name or as at = (from =, to =), not both",
               p->name);
  if (has_at && (has_from || has_to))
    luaL_error(L, "probe '%s': at = makes a point probe, from = and to = a face: give one",
               p->name);
  if (has_from != has_to)
    luaL_error(L, "probe '%s': a face needs both ends, from = {x0, y0} and to = {x1, y1}", p->name);
  if (given <= 0 && !has_at && !has_from)
    luaL_error(L, "probe '%s': where? give %s", p->name, forms);
  for (int k = 0; k < given; ++k) {
    lua_geti(L, 1, first + k);
    to_vec(L, "probe", k == 0 ? "its point (or the face's first end)" : "the face's second end",
           k == 0 ? p->x : p->b);
    lua_pop(L, 1);
  }
  p->face = given == 2 || has_from;
  /* a disc (3-D): a point, its radius and its normal */
  const double radius = get_number(L, 1, "probe", "radius", NAN);
  double nrm[3] = {0.0, 0.0, 0.0};
  const int has_normal = get_vec(L, 1, "probe", "normal", nrm);
  if (!isnan(radius) || has_normal) {
    if (s->dim == 2)
      luaL_error(L,
                 "probe '%s': radius = and normal = make a disc, a face of a 3-D scene; a 2-D "
                 "face is { \"%s\", {x0, y0}, {x1, y1} }",
                 p->name, p->name);
    if (p->face || isnan(radius) || !has_normal)
      luaL_error(L, "probe '%s': a disc is its centre, radius = R and normal = {nx, ny, nz}",
                 p->name);
    const double len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (!(radius > 0.0) || !(len > 0.0) || !isfinite(len))
      luaL_error(L, "probe '%s': a disc needs a positive radius (not %f) and a nonzero normal",
                 p->name, radius);
    for (int a = 0; a < 3; ++a) p->normal[a] = nrm[a] / len;
    p->radius = radius;
    p->face = 2;
  }
  const double np = get_number(L, 1, "probe", "points", 0);
  char num[96]; /* lua_pushfstring has no %g */
  snprintf(num, sizeof num, "%g", np);
  if (p->face != 1 && np != 0)
    luaL_error(L,
               "probe '%s': points = %s belongs to a face, { \"%s\", {x0, y0}, {x1, y1}, "
               "points = N }",
               p->name, num, p->name);
  if (p->face && np != 0 && !(np >= 1 && np <= 1e4 && np == floor(np)))
    luaL_error(L, "probe '%s': points = %s must be a whole number from 1 to 10000", p->name, num);
  if (s->dim == 3)
    snprintf(num, sizeof num, "(%g, %g, %g)", p->x[0], p->x[1], p->x[2]);
  else
    snprintf(num, sizeof num, "(%g, %g)", p->x[0], p->x[1]);
  if (p->face == 1 && p->b[0] == p->x[0] && p->b[1] == p->x[1] && p->b[2] == p->x[2])
    luaL_error(L,
               "probe '%s': the face's two ends are the same point %s; a point probe takes "
               "one point",
               p->name, num);
  p->npts = p->face == 1 ? (int)np : 1; /* a face's 0, a disc's: from dr, at finish */
  return 0;
}

/* profile { } and profile_error { }: interpolation = "shepard" (0) or "linear" (1, sim_sample) */
static const char *const interpolations[] = {"shepard", "linear", NULL};

static int l_profile(lua_State *L)
{
  static const char *const keys[] = {"name", "from", "to", "points", "interpolation", NULL};
  struct loader *ld = loader_of(L);
  struct scene *s = ld->s;
  need_table(L, "profile");
  check_keys(L, 1, "profile", keys, 1);
  struct scene_profile_line *p = grow(L, (void **)&s->profiles, &s->nprofiles, sizeof *p);
  p->line = current_line(L);
  lua_geti(L, 1, 1);
  if (lua_type(L, -1) == LUA_TSTRING) snprintf(p->name, SCENE_NAME, "%s", lua_tostring(L, -1));
  lua_pop(L, 1);
  if (p->name[0] == '\0') get_name(L, 1, "profile", "name", p->name, "");
  if (p->name[0] == '\0') luaL_error(L, "profile: needs a name");
  if (!get_vector(L, 1, "profile", "from", p->a) || !get_vector(L, 1, "profile", "to", p->b))
    luaL_error(L, "profile: needs from = %s and to = %s", s->dim == 3 ? "{x, y, z}" : "{x, y}",
               s->dim == 3 ? "{x, y, z}" : "{x, y}");
  double np = get_number(L, 1, "profile", "points", 101);
  if (np < 2 || np > 1e5 || np != floor(np)) luaL_error(L, "profile: points must be 2 to 100000");
  p->npts = (int)np;
  p->order = get_choice(L, 1, "profile", "interpolation", interpolations, 0);
  return 0;
}

static void add_force(lua_State *L, struct scene *s, int idx)
{
  if (lua_type(L, idx) != LUA_TSTRING) luaL_error(L, "force: wall groups are names");
  char(*f)[SCENE_NAME] = grow(L, (void **)&s->forces, &s->nforces, sizeof *f);
  snprintf(*f, SCENE_NAME, "%s", lua_tostring(L, idx));
}

/* force "lid" or force { "lid", "walls" } */
static int l_force(lua_State *L)
{
  struct loader *ld = loader_of(L);
  if (lua_gettop(L) == 1 && lua_istable(L, 1)) {
    int n = (int)lua_rawlen(L, 1);
    if (n == 0) luaL_error(L, "force: name the wall groups, e.g. force { \"lid\" }");
    for (int i = 1; i <= n; ++i) {
      lua_geti(L, 1, i);
      add_force(L, ld->s, lua_gettop(L));
      lua_pop(L, 1);
    }
  } else if (lua_gettop(L) == 1) {
    add_force(L, ld->s, 1);
  } else {
    luaL_error(L, "force: name the wall groups, e.g. force { \"lid\" }");
  }
  return 0;
}

/* run { checks = { every = 10, cluster_h = 0.125, ... } }: the health-check thresholds
 * (struct scene_checks; defaults in scene_checks_default). cluster_spacing, the clustering
 * distance in dr until cluster_h replaced it, is refused with its equivalent. */
static void run_checks(lua_State *L, int idx, struct scene *s)
{
  static const char *const keys[] = {
      "every", "cluster_h", "cluster_fraction", "energy", "wall_depth", "escaped", NULL};
  const char *fn = "run: checks";
  struct scene_checks *c = &s->checks;
  if (!lua_istable(L, idx)) luaL_error(L, "%s: expects a table { every = 10, ... }", fn);
  lua_getfield(L, idx, "cluster_spacing");
  if (!lua_isnil(L, -1)) {
    const double v = lua_isnumber(L, -1) ? lua_tonumber(L, -1) : 0.5;
    char eq[96]; /* lua_pushfstring has no %g */
    snprintf(eq, sizeof eq, "cluster_spacing = %g is cluster_h = %g", v, v / 2.0);
    luaL_error(L,
               "%s: cluster_spacing (a distance in dr) was replaced by cluster_h, the distance in "
               "smoothing lengths h: %s where h = 2 dr (isph-usaw, wcsph-usaw; `clsph info` "
               "prints a scene's h); the default, cluster_h = 0.125, lets healthy runs through",
               fn, eq);
  }
  lua_pop(L, 1);
  check_keys(L, idx, fn, keys, 0);
  double every = get_number(L, idx, fn, "every", c->every);
  if (!(every >= 1.0 && every <= 1e9 && every == floor(every)))
    luaL_error(L, "%s: every must be a whole number of steps, at least 1", fn);
  c->every = (int)every;
  c->cluster_h = get_number(L, idx, fn, "cluster_h", c->cluster_h);
  c->cluster_fraction = get_number(L, idx, fn, "cluster_fraction", c->cluster_fraction);
  c->energy = get_number(L, idx, fn, "energy", c->energy);
  c->wall_depth = get_number(L, idx, fn, "wall_depth", c->wall_depth);
  if (c->cluster_h < 0.0 || c->cluster_fraction < 0.0 || c->energy < 0.0 || c->wall_depth < 0.0)
    luaL_error(L, "%s: thresholds must not be negative", fn);
  c->escaped = get_number(L, idx, fn, "escaped", c->escaped);
  if (!(c->escaped >= 0.0 && c->escaped <= 1.0)) {
    char v[32]; /* lua_pushfstring has no %g */
    snprintf(v, sizeof v, "%g", c->escaped);
    luaL_error(L,
               "%s: escaped is the fraction of the fluid that may leave the domain before the "
               "run stops: from 0 (none) to 1, not %s",
               fn, v);
  }
}

static int l_run(lua_State *L)
{
  static const char *const keys[] = {"t_end",         "output_every", "checkpoint_every",
                                     "cfl",           "dt",           "sample_every",
                                     "max_snapshots", "checks",       NULL};
  struct loader *ld = loader_of(L);
  struct scene *s = ld->s;
  need_table(L, "run");
  once(L, &ld->line_run, "run");
  s->run_line = ld->line_run;
  check_keys(L, 1, "run", keys, 0);
  s->t_end = get_number(L, 1, "run", "t_end", NAN);
  if (isnan(s->t_end)) luaL_error(L, "run: needs t_end, the end time (s)");
  /* t_end is always a parameter, so --set t_end=... shortens any run: a case that declares it
   * computes run { t_end } from it (which may differ: run { t_end = 2 * t_end } is what runs),
   * a case that does not gets it declared here with run's value */
  int declared = 0;
  for (int i = 0; i < s->nparams; ++i) declared |= strcmp(s->params[i].name, "t_end") == 0;
  if (!declared) {
    struct scene_param *p = grow(L, (void **)&s->params, &s->nparams, sizeof *p);
    snprintf(p->name, SCENE_NAME, "t_end");
    p->value = s->t_end;
    for (int k = 0; k < ld->nsets; ++k) {
      if (strcmp(ld->set_names[k], "t_end") == 0) {
        p->value = ld->set_values[k];
        p->overridden = 1;
        ld->set_used[k] = 1;
      }
    }
  }
  if (!declared) s->t_end = scene_param(s, "t_end", s->t_end);
  if (!(s->t_end > 0.0)) luaL_error(L, "run: t_end must be a positive time, not %f", s->t_end);
  s->output_every = get_number(L, 1, "run", "output_every", 0.0);
  s->checkpoint_every = get_number(L, 1, "run", "checkpoint_every", 0.0);
  s->sample_every = get_number(L, 1, "run", "sample_every", 0.0);
  if (s->sample_every < 0.0) luaL_error(L, "run: sample_every must not be negative");
  s->cfl = get_number(L, 1, "run", "cfl", 1.0);
  if (s->output_every < 0.0 || s->checkpoint_every < 0.0)
    luaL_error(L, "run: output_every and checkpoint_every must not be negative");
  s->max_snapshots = get_number(L, 1, "run", "max_snapshots", 10000.0);
  if (!(s->max_snapshots >= 1.0 && s->max_snapshots <= 1e9))
    luaL_error(L, "run: max_snapshots must be from 1 to 1e9, not %f", s->max_snapshots);
  if (!(s->cfl > 0.0)) luaL_error(L, "run: cfl must be positive, not %f", s->cfl);
  s->dt = get_number(L, 1, "run", "dt", 0.0);
  if (s->dt < 0.0) luaL_error(L, "run: dt must be a positive time step, not %f", s->dt);
  lua_getfield(L, 1, "checks");
  if (!lua_isnil(L, -1)) run_checks(L, lua_gettop(L), s);
  lua_pop(L, 1);
  return 0;
}

/* render { field = "p", range = {0, 1e4}, colormap = "viridis" }: how frames show the case. The
 * field's name is checked against the scheme's fields when a run starts. */
static int l_render(lua_State *L)
{
  static const char *const keys[] = {"field", "range", "colormap", "camera", NULL};
  static const char *const maps[] = {"auto", "viridis", "coolwarm", "kind", NULL};
  static const char *const cam_keys[] = {"eye", "look_at", "up", "fov", NULL};
  struct loader *ld = loader_of(L);
  struct scene_render *r = &ld->s->render;
  need_table(L, "render");
  once(L, &r->line, "render");
  check_keys(L, 1, "render", keys, 0);
  r->on = 1;
  get_name(L, 1, "render", "field", r->field, "");
  lua_getfield(L, 1, "range");
  if (!lua_isnil(L, -1)) {
    if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 2)
      luaL_error(L, "render: range must be {low, high}, e.g. range = {0, 1000}");
    double lohi[2] = {get_index_number(L, lua_gettop(L), "render", 1, "range"),
                      get_index_number(L, lua_gettop(L), "render", 2, "range")};
    if (!(lohi[0] < lohi[1]))
      luaL_error(L, "render: range {%f, %f}: the low end must be below the high end", lohi[0],
                 lohi[1]);
    r->fixed = 1;
    r->range[0] = lohi[0];
    r->range[1] = lohi[1];
  }
  lua_pop(L, 1);
  int m = get_choice(L, 1, "render", "colormap", maps, 0);
  snprintf(r->colormap, SCENE_NAME, "%s", maps[m]);
  /* camera = { eye = {x, y, z}, look_at = {x, y, z}, up = {0, 0, 1}, fov = 30 }: 3-D frames */
  if (lua_getfield(L, 1, "camera") != LUA_TNIL) {
    if (ld->s->dim != 3)
      luaL_error(L, "render: camera is for 3-D scenes (declare the domain { x0, y0, z0, x1, y1, "
                    "z1 } first); 2-D frames show the whole domain");
    const int t = lua_gettop(L);
    if (!lua_istable(L, t))
      luaL_error(L, "render: camera must be { eye = {x, y, z}, look_at = {x, y, z}, up = ..., "
                    "fov = ... }");
    check_keys(L, t, "render camera", cam_keys, 0);
    if (!get_vector(L, t, "render camera", "eye", r->eye) ||
        !get_vector(L, t, "render camera", "look_at", r->look_at))
      luaL_error(L, "render: camera needs eye = {x, y, z} and look_at = {x, y, z}");
    r->up[0] = r->up[1] = 0.0;
    r->up[2] = 1.0;
    get_vector(L, t, "render camera", "up", r->up);
    r->fov = get_number(L, t, "render camera", "fov", 30.0);
    r->camera = 1; /* (checked with the frames' options: render_check_camera) */
  }
  lua_pop(L, 1);
  return 0;
}

/* ---- loading ---- */

static enum clsph_status parse_sets(int nsets, char *const *sets, struct loader *ld)
{
  enum clsph_status st = CLSPH_OK;
  ld->nsets = nsets;
  ld->set_names = calloc((size_t)nsets + 1, sizeof *ld->set_names);
  ld->set_values = calloc((size_t)nsets + 1, sizeof *ld->set_values);
  ld->set_used = calloc((size_t)nsets + 1, sizeof *ld->set_used);
  CLSPH_CHECK(ld->set_names && ld->set_values && ld->set_used, CLSPH_E_NOMEM, "out of memory");
  for (int k = 0; k < nsets; ++k) {
    const char *eq = strchr(sets[k], '=');
    size_t len = eq != NULL ? (size_t)(eq - sets[k]) : 0;
    CLSPH_CHECK(eq != NULL && len > 0 && len < SCENE_NAME, CLSPH_E_INPUT,
                "--set %s: write name=value, e.g. --set dr=0.005", sets[k]);
    memcpy(ld->set_names[k], sets[k], len);
    ld->set_names[k][len] = '\0';
    char *end = NULL;
    errno = 0;
    ld->set_values[k] = strtod(eq + 1, &end);
    CLSPH_CHECK(errno == 0 && end != eq + 1 && *end == '\0' && isfinite(ld->set_values[k]),
                CLSPH_E_INPUT, "--set %s: '%s' is not a number", sets[k], eq + 1);
    for (int j = 0; j < k; ++j)
      CLSPH_CHECK(strcmp(ld->set_names[j], ld->set_names[k]) != 0, CLSPH_E_INPUT,
                  "--set %s: '%s' is set twice", sets[k], ld->set_names[k]);
  }
done:
  return st;
}

static void open_sandbox(lua_State *L)
{
  static const luaL_Reg libs[] = {{LUA_GNAME, luaopen_base},
                                  {LUA_MATHLIBNAME, luaopen_math},
                                  {LUA_STRLIBNAME, luaopen_string},
                                  {LUA_TABLIBNAME, luaopen_table}};
  for (size_t i = 0; i < sizeof libs / sizeof *libs; ++i) {
    luaL_requiref(L, libs[i].name, libs[i].func, 1);
    lua_pop(L, 1);
  }
  static const char *const removed[] = {"dofile", "loadfile", "load", "require", "collectgarbage"};
  for (size_t i = 0; i < sizeof removed / sizeof *removed; ++i) {
    lua_pushnil(L);
    lua_setglobal(L, removed[i]);
  }
}

static void register_api(lua_State *L, struct loader *ld)
{
  static const luaL_Reg api[] = {
      {"param", l_param},
      {"domain", l_domain},
      {"particles", l_particles},
      {"scheme", l_scheme},
      {"fluid", l_fluid},
      {"fill", l_fill},
      {"wall", l_wall},
      {"box_wall", l_box_wall},
      {"sphere_wall", l_sphere_wall},
      {"cylinder_wall", l_cylinder_wall},
      {"stl_wall", l_stl_wall},
      {"arc", l_arc},
      {"circle", l_circle},
      {"inflow", l_inflow},
      {"outflow", l_outflow},
      {"probe", l_probe},
      {"profile", l_profile},
      {"force", l_force},
      {"run", l_run},
      {"render", l_render},
      {"turbulence", l_turbulence},
      {"reference", l_reference},
  };
  for (size_t i = 0; i < sizeof api / sizeof *api; ++i) {
    lua_pushlightuserdata(L, ld);
    lua_pushcclosure(L, api[i].func, 1);
    lua_setglobal(L, api[i].name);
  }
}

static int cmp_param(const void *a, const void *b)
{
  return strcmp(((const struct scene_param *)a)->name, ((const struct scene_param *)b)->name);
}

static int cmp_option(const void *a, const void *b)
{
  return strcmp(((const struct scene_option *)a)->key, ((const struct scene_option *)b)->key);
}

/* Is x in the domain's box (its edges included, to a millionth of its size)? */
static int in_domain(const struct scene *s, const double *x)
{
  for (int a = 0; a < s->dim; ++a) {
    const double tol = 1e-6 * (s->hi[a] - s->lo[a]);
    if (!(x[a] >= s->lo[a] - tol && x[a] <= s->hi[a] + tol)) return 0;
  }
  return 1;
}

/* After the script: what must be there, and --set names nobody declared. */
static enum clsph_status finish(const char *path, struct loader *ld)
{
  enum clsph_status st = CLSPH_OK;
  struct scene *s = ld->s;
  const char **names = NULL;
  char hint[512];
  CLSPH_CHECK(ld->line_domain, CLSPH_E_INPUT, "%s: declares no domain { x0, y0, x1, y1 }", path);
  CLSPH_CHECK(ld->line_particles, CLSPH_E_INPUT, "%s: declares no particles { dr = ... }", path);
  CLSPH_CHECK(ld->line_scheme, CLSPH_E_INPUT, "%s: declares no scheme \"name\"", path);
  CLSPH_CHECK(ld->line_run, CLSPH_E_INPUT, "%s: declares no run { t_end = ... }", path);
  CLSPH_CHECK(s->nregions > 0, CLSPH_E_INPUT, "%s: declares no fluid region (fill { ... })", path);
  names = calloc((size_t)s->nparams + 1, sizeof *names);
  CLSPH_CHECK(names != NULL, CLSPH_E_NOMEM, "out of memory");
  for (int i = 0; i < s->nparams; ++i) names[i] = s->params[i].name;
  for (int k = 0; k < ld->nsets; ++k) {
    if (ld->set_used[k]) continue;
    spell_suggest(ld->set_names[k], names, hint, sizeof hint);
    CLSPH_CHECK(0, CLSPH_E_INPUT, "--set %s: %s declares no parameter '%s'%s", ld->set_names[k],
                path, ld->set_names[k], hint);
  }
  if (!s->rho0) s->rho0 = 1000.0;       /* no fluid {} declaration: water at rest */
  for (int w = 0; w < s->nwalls; ++w) { /* the STL surfaces: read, placed and checked */
    struct scene_wall *wl = &s->walls[w];
    if (wl->shape != SCENE_MESH) continue;
    char where[1200];
    snprintf(where, sizeof where, "%s:%d: stl_wall", path, wl->line);
    wl->mesh = calloc(1, sizeof *wl->mesh);
    CLSPH_CHECK(wl->mesh != NULL, CLSPH_E_NOMEM, "out of memory");
    CLSPH_TRY(mesh_load(wl->stl, where, wl->stl_scale, wl->stl_offset, wl->mesh));
    memcpy(wl->box3, wl->mesh->box, sizeof wl->box3);
  }
  if (s->dim == 3) { /* what 3-D scenes have: box, sphere and cylinder walls and fills */
    for (int w = 0; w < s->nwalls; ++w)
      CLSPH_CHECK(s->walls[w].box3d, CLSPH_E_INPUT,
                  "%s:%d: wall (group '%s') is a 2-D polyline (wall, arc, circle or a box_wall "
                  "declared before the domain) in a 3-D scene: 3-D walls are box_wall { x0, y0, "
                  "z0, x1, y1, z1 }, sphere_wall { }, cylinder_wall { } and stl_wall { } after "
                  "domain { }",
                  path, s->walls[w].line, s->walls[w].group);
    for (int r = 0; r < s->nregions; ++r)
      CLSPH_CHECK(s->regions[r].npts == 0, CLSPH_E_INPUT,
                  "%s:%d: fill '%s' is 2-D (declared before the 3-D domain?): 3-D fills are boxes "
                  "{ x0, y0, z0, x1, y1, z1 } after domain { }",
                  path, s->regions[r].line, s->regions[r].name);
    const struct {
      int count, line;
      const char *what;
    } only2[] = {
        {s->nsections, s->nsections ? s->sections[0].line : 0, "inflow and outflow sections"},
        {s->flow.on, s->flow.line, "flow_rate_control"},
        {s->turb.on, s->turb.line, "turbulence"},
    };
    CLSPH_CHECK(s->nforces == 0, CLSPH_E_INPUT,
                "%s: force { \"%s\" }: wall forces are 2-D only for now; this scene is 3-D", path,
                s->nforces > 0 ? s->forces[0] : "");
    for (size_t k = 0; k < sizeof only2 / sizeof *only2; ++k)
      CLSPH_CHECK(only2[k].count == 0, CLSPH_E_INPUT,
                  "%s:%d: %s are 2-D only for now; this scene is 3-D (its domain gives z)", path,
                  only2[k].line, only2[k].what);
  }
  if (s->flow.on) { /* the slice must cut the domain: on a periodic axis, less than a period */
    const struct scene_flow_control *c = &s->flow;
    const double len = s->hi[0] - s->lo[0];
    CLSPH_CHECK(s->periodic[0] ? c->slice[1] - c->slice[0] < len
                               : c->slice[0] >= s->lo[0] && c->slice[1] <= s->hi[0],
                CLSPH_E_INPUT,
                "%s:%d: fluid: flow_rate_control: the slice {%g, %g} must lie in the domain's x "
                "range [%g, %g]%s",
                path, c->line, c->slice[0], c->slice[1], s->lo[0], s->hi[0],
                s->periodic[0] ? " (periodic: be narrower than the period)" : "");
  }
  if (s->turb.on) { /* the model's values against the scene (Wang, Sun & Hu eqs 6, 10, 11) */
    const struct scene_turbulence *t = &s->turb;
    const double cmu = 0.09, y_p = t->y_p > 0.0 ? t->y_p : 0.5 * s->dr;
    const double size = fmin(s->hi[0] - s->lo[0], s->hi[1] - s->lo[1]);
    CLSPH_CHECK(s->nu > 0.0, CLSPH_E_INPUT,
                "%s:%d: turbulence: the wall model needs the molecular viscosity: give fluid { "
                "viscosity = (m²/s) }",
                path, t->line);
    /* the turbulence's length scale C_μ^¾ k^{3/2} / ε: larger than the domain, k and ε do not
     * belong together (ε far too small for k) */
    const double ell = pow(cmu, 0.75) * pow(t->k, 1.5) / t->epsilon;
    CLSPH_CHECK(ell <= size, CLSPH_E_INPUT,
                "%s:%d: turbulence: k = %g and epsilon = %g imply a turbulence length scale "
                "C_mu^3/4 k^3/2 / epsilon = %g m, larger than the domain (%g m): epsilon is too "
                "small for k (or k too large)",
                path, t->line, t->k, t->epsilon, ell, size);
    CLSPH_CHECK(y_p < 0.5 * size, CLSPH_E_INPUT,
                "%s:%d: turbulence: y_p = %g m is more than half the domain (%g m)", path, t->line,
                y_p, size);
  }
  /* an entry's k and ε: only under the model, and a length scale that fits the entry */
  for (int q = 0; q < s->nsections; ++q) {
    const struct scene_section *c = &s->sections[q];
    if (c->kind != SCENE_INFLOW) continue;
    const int k_table = c->nprof > 0 && !isnan(c->prof[1]),
              e_table = c->nprof > 0 && !isnan(c->prof[2]), table = k_table || e_table;
    if (isnan(c->k) && !table) continue;
    CLSPH_CHECK(s->turb.on, CLSPH_E_INPUT,
                "%s:%d: inflow '%s': k and epsilon belong to the k-epsilon model: declare "
                "turbulence { model = \"k-epsilon\", ... } or drop them",
                path, c->line, c->name);
    const double width = hypot(c->b[0] - c->a[0], c->b[1] - c->a[1]);
    /* each sample of a table (or the two numbers) */
    const int n = table ? c->nprof : 1;
    for (int i = 0; i < n; ++i) {
      const double k = k_table ? c->prof[3 * i + 1] : c->k,
                   e = e_table ? c->prof[3 * i + 2] : c->epsilon;
      const double ell = pow(0.09, 0.75) * pow(k, 1.5) / e, nut = 0.09 * k * k / e;
      char where[64] = "";
      if (table) snprintf(where, sizeof where, " at s = %g m", width * i / (double)(n - 1));
      CLSPH_CHECK(ell <= width, CLSPH_E_INPUT,
                  "%s:%d: inflow '%s': k = %g and epsilon = %g%s are inconsistent: their length "
                  "scale C_mu^3/4 k^3/2 / epsilon = %g m is larger than the entry (%g m wide), "
                  "an eddy viscosity C_mu k^2/epsilon = %g m²/s (%.3g times nu); raise epsilon "
                  "or lower k (a length scale of about 0.07 of the entry's width is usual)",
                  path, c->line, c->name, k, e, where, ell, width, nut,
                  s->nu > 0.0 ? nut / s->nu : HUGE_VAL);
    }
  }
  /* probes and profiles sample the fluid: outside the domain there is none (a column of NaN) */
  for (int k = 0; k < s->nprobes; ++k) {
    struct scene_probe *p = &s->probes[k];
    char at[96], end[96], box[160];
    if (s->dim == 3) {
      snprintf(at, sizeof at, "(%g, %g, %g)", p->x[0], p->x[1], p->x[2]);
      snprintf(end, sizeof end, "(%g, %g, %g)", p->b[0], p->b[1], p->b[2]);
      snprintf(box, sizeof box, "{%g, %g, %g, %g, %g, %g}", s->lo[0], s->lo[1], s->lo[2], s->hi[0],
               s->hi[1], s->hi[2]);
    } else {
      snprintf(at, sizeof at, "(%g, %g)", p->x[0], p->x[1]);
      snprintf(end, sizeof end, "(%g, %g)", p->b[0], p->b[1]);
      snprintf(box, sizeof box, "{%g, %g, %g, %g}", s->lo[0], s->lo[1], s->hi[0], s->hi[1]);
    }
    CLSPH_CHECK(in_domain(s, p->x), CLSPH_E_INPUT,
                "%s:%d: probe '%s' at %s lies outside the domain %s", path, p->line, p->name, at,
                box);
    CLSPH_CHECK(p->face != 1 || in_domain(s, p->b), CLSPH_E_INPUT,
                "%s:%d: probe '%s': the face's end %s lies outside the domain %s", path, p->line,
                p->name, end, box);
    for (int j = 0; j < k; ++j)
      CLSPH_CHECK(strcmp(s->probes[j].name, p->name) != 0, CLSPH_E_INPUT,
                  "%s:%d: probe '%s' is declared twice (first at line %d): probes.csv names its "
                  "columns after the probe",
                  path, p->line, p->name, s->probes[j].line);
    /* a face's points dr/4 apart or closer: the interpolated field varies over h >= dr */
    double len = 0.0;
    for (int a = 0; a < s->dim; ++a) len += (p->b[a] - p->x[a]) * (p->b[a] - p->x[a]);
    len = sqrt(len) / s->dr;
    CLSPH_CHECK(p->face != 1 || p->npts > 0 || 4.0 * len <= 1e4, CLSPH_E_INPUT,
                "%s:%d: probe '%s': the face is %g dr long, more than 10000 points at dr/4; give "
                "points = N (at most 10000)",
                path, p->line, p->name, len);
    if (p->face == 1 && p->npts == 0) p->npts = (int)fmax(2.0, ceil(4.0 * len));
    if (p->face == 2) p->npts = scene_probe_points(p, 3, s->dr, NULL);
  }
  for (int k = 0; k < s->nprofiles; ++k) {
    const struct scene_profile_line *p = &s->profiles[k];
    if (s->dim == 3)
      CLSPH_CHECK(in_domain(s, p->a) && in_domain(s, p->b), CLSPH_E_INPUT,
                  "%s:%d: profile '%s' from (%g, %g, %g) to (%g, %g, %g) leaves the domain "
                  "{%g, %g, %g, %g, %g, %g}",
                  path, p->line, p->name, p->a[0], p->a[1], p->a[2], p->b[0], p->b[1], p->b[2],
                  s->lo[0], s->lo[1], s->lo[2], s->hi[0], s->hi[1], s->hi[2]);
    CLSPH_CHECK(in_domain(s, p->a) && in_domain(s, p->b), CLSPH_E_INPUT,
                "%s:%d: profile '%s' from (%g, %g) to (%g, %g) leaves the domain {%g, %g, %g, %g}",
                path, p->line, p->name, p->a[0], p->a[1], p->b[0], p->b[1], s->lo[0], s->lo[1],
                s->hi[0], s->hi[1]);
  }
  qsort(s->params, (size_t)s->nparams, sizeof *s->params, cmp_param);
  /* by name: Lua visits a table's keys in an order that changes from run to run */
  qsort(s->options, (size_t)s->noptions, sizeof *s->options, cmp_option);
done:
  free(names);
  return st;
}

enum clsph_status case_load(const char *path, int nsets, char *const *sets,
                            const struct case_limits *limits, struct scene *out,
                            struct case_script **script)
{
  enum clsph_status st = CLSPH_OK;
  struct scene s;
  struct loader ld;
  struct case_script *cs = NULL;
  struct case_limits lim;
  memset(&s, 0, sizeof s);
  memset(&ld, 0, sizeof ld);
  ld.s = &s;
  case_limits_default(&lim);
  if (limits != NULL) lim = *limits;

  CLSPH_CHECK(strlen(path) < sizeof s.case_path, CLSPH_E_INPUT, "case path too long: %s", path);
  snprintf(s.case_path, sizeof s.case_path, "%s", path);
  const char *base = strrchr(path, '/');
  base = base != NULL ? base + 1 : path;
  snprintf(s.name, sizeof s.name, "%s", base);
  char *dot = strrchr(s.name, '.');
  if (dot != NULL && strcmp(dot, ".lua") == 0) *dot = '\0';
  s.dim = 2;
  scene_checks_default(&s.checks);
  CLSPH_TRY(parse_sets(nsets, sets, &ld));

  /* the sandbox: its own allocator with a ceiling, and an instruction budget per entry */
  cs = calloc(1, sizeof *cs);
  CLSPH_CHECK(cs != NULL, CLSPH_E_NOMEM, "out of memory");
  cs->sb.limit = (size_t)lim.memory;
  cs->sb.budget = (long long)lim.instructions;
  cs->sb.path = s.case_path;
  cs->L = lua_newstate(sandbox_alloc, &cs->sb);
  CLSPH_CHECK(cs->L != NULL, CLSPH_E_NOMEM, "cannot create a Lua state");
  lua_State *L = cs->sb.L = cs->L;
  lua_sethook(L, sandbox_hook, LUA_MASKCOUNT, SANDBOX_HOOK_EVERY);
  open_sandbox(L);
  register_api(L, &ld);
  struct stat sb;
  CLSPH_CHECK(stat(path, &sb) == 0, CLSPH_E_INPUT, "cannot read case %s: %s", path,
              strerror(errno));
  CLSPH_CHECK(!S_ISDIR(sb.st_mode), CLSPH_E_INPUT,
              "case %s is a folder: name a case script, e.g. cases/cavity.lua", path);
  int err = luaL_loadfilex(L, path, "t"); /* text only: no precompiled chunks */
  if (err == LUA_ERRFILE) {
    log_error("cannot read case %s: %s", path, lua_tostring(L, -1));
    st = CLSPH_E_INPUT;
    goto done;
  }
  if (err != LUA_OK) {
    log_error("%s", lua_tostring(L, -1));
    st = CLSPH_E_INPUT;
    goto done;
  }
  CLSPH_TRY(sandbox_call(&cs->sb, 0, 0, "the case script"));
  CLSPH_TRY(finish(path, &ld));
  *out = s;
  memset(&s, 0, sizeof s);
  if (script != NULL) {
    cs->sb.path = out->case_path;
    out->velocity_fn.eval = fill_velocity;
    out->velocity_fn.scalar = fill_scalar;
    out->velocity_fn.ctx = cs;
    cs->dim = out->dim;
    *script = cs;
    cs = NULL;
  }
done:
  case_close(cs);
  scene_free(&s);
  free(ld.set_names);
  free(ld.set_values);
  free(ld.set_used);
  return st;
}

/* ---- metrics ---- */

/* why a callback refused (its own words), or a device or memory failure already logged */
static const char *why_of(const struct case_sim_api *api)
{
  return api->why[0] != '\0' ? api->why : "the run could not provide it (see above)";
}

static const struct case_sim_api *api_of(lua_State *L)
{
  return lua_touserdata(L, lua_upvalueindex(1));
}

static int kind_of(lua_State *L, int idx)
{
  static const char *const kinds[] = {"fluid", "vertex", "dummy", "inflow", "outflow", NULL};
  if (lua_isnoneornil(L, idx)) return 0;
  const char *k = luaL_checkstring(L, idx);
  if (strcmp(k, "all") == 0) return -1;
  for (int i = 0; kinds[i] != NULL; ++i)
    if (strcmp(k, kinds[i]) == 0) return i;
  return luaL_error(L, "unknown particle kind '%s' (fluid, vertex, dummy, inflow, outflow, all)",
                    k);
}

/* A region {x0, y0, x1, y1} at idx into box (x0 < x1, y0 < y1). */
static void region_of(lua_State *L, int idx, double box[4])
{
  if (lua_rawlen(L, idx) != 4)
    luaL_error(L, "sim: a region is {x0, y0, x1, y1}, the box x0 <= x <= x1, y0 <= y <= y1");
  for (int k = 0; k < 4; ++k) {
    lua_rawgeti(L, idx, k + 1);
    if (lua_type(L, -1) != LUA_TNUMBER)
      luaL_error(L, "sim: region entry %d is not a number", k + 1);
    box[k] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  if (!(box[0] <= box[2] && box[1] <= box[3]))
    luaL_error(L, "sim: the region {%f, %f, %f, %f} is empty (x0 <= x1 and y0 <= y1 needed)",
               box[0], box[1], box[2], box[3]);
}

/* sim.min/max/mean(field [, component [, kind]] [, region]) over the fluid particles unless a
 * kind is given, in the box region = {x0, y0, x1, y1} when one is (nil when no particle is in
 * it) */
static int l_stat(lua_State *L, int which)
{
  const struct case_sim_api *api = api_of(L);
  const char *field = luaL_checkstring(L, 1);
  int comp = (int)luaL_optinteger(L, 2, 1) - 1;
  double box[4];
  const double *region = NULL;
  int kind = 0;
  if (lua_istable(L, 3)) {
    region_of(L, 3, box);
    region = box;
  } else {
    kind = kind_of(L, 3);
    if (lua_istable(L, 4)) {
      region_of(L, 4, box);
      region = box;
    }
  }
  double v[3];
  size_t count = 0;
  if (api->stats(api->ctx, field, comp, kind, region, &v[0], &v[1], &v[2], &count) != CLSPH_OK)
    return luaL_error(L, "sim: no statistics for field '%s' component %d: %s", field, comp + 1,
                      why_of(api));
  if (count == 0 && region != NULL) {
    lua_pushnil(L);
    return 1;
  }
  if (count == 0) return luaL_error(L, "sim: no particle of that kind");
  lua_pushnumber(L, v[which]);
  return 1;
}

/* sim.series(name): what sample() recorded under `name` so far, a table of arrays `time` and
 * `value` (the rows of series.csv, a restart's included) */
static int l_series(lua_State *L)
{
  const struct case_sim_api *api = api_of(L);
  const char *name = luaL_checkstring(L, 1);
  size_t n = 0;
  double *rows = NULL;
  if (api->series == NULL || api->series(api->ctx, name, &n, &rows) != CLSPH_OK)
    return luaL_error(L, "sim.series: %s", api->series ? why_of(api) : "the case has no sample()");
  lua_createtable(L, 0, 2);
  const char *names[] = {"time", "value"};
  for (int c = 0; c < 2; ++c) {
    lua_createtable(L, (int)n, 0);
    for (size_t i = 0; i < n; ++i) {
      lua_pushnumber(L, rows[2 * i + (size_t)c]);
      lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    lua_setfield(L, -2, names[c]);
  }
  free(rows);
  return 1;
}

static int l_min(lua_State *L)
{
  return l_stat(L, 0);
}

static int l_max(lua_State *L)
{
  return l_stat(L, 1);
}

static int l_mean(lua_State *L)
{
  return l_stat(L, 2);
}

/* sim.probe(name, field [, component]): the probe's value now (its point's, or its face's mean;
 * NaN where there is no fluid) */
static int l_probe_now(lua_State *L)
{
  const struct case_sim_api *api = api_of(L);
  const char *name = luaL_checkstring(L, 1), *field = luaL_checkstring(L, 2);
  int comp = (int)luaL_optinteger(L, 3, 1) - 1;
  double v = 0.0;
  if (api->probe == NULL || api->probe(api->ctx, name, field, comp, &v) != CLSPH_OK)
    return luaL_error(L, "sim.probe: no value of '%s' (component %d) at probe '%s': %s", field,
                      comp + 1, name, why_of(api));
  lua_pushnumber(L, v);
  return 1;
}

/* sim.sample(field, x, y [, component [, interpolation]]) in 2-D, or
 * sim.sample(field, {x, y [, z]} [, component [, interpolation]]) (3-D needs the table):
 * interpolation "shepard" (the default) or "linear" (first-order moving least squares,
 * sim_sample) */
static int l_sample(lua_State *L)
{
  const struct case_sim_api *api = api_of(L);
  const char *field = luaL_checkstring(L, 1);
  double pt[3] = {0.0, 0.0, 0.0}, v = 0.0;
  int ncoord = 2, next = 4;
  if (lua_istable(L, 2)) {
    ncoord = (int)luaL_len(L, 2);
    if (ncoord != 2 && ncoord != 3)
      return luaL_error(L, "sim.sample: the point must be {x, y} or {x, y, z}, not %d numbers",
                        ncoord);
    for (int a = 0; a < ncoord; ++a) {
      lua_rawgeti(L, 2, a + 1);
      if (!lua_isnumber(L, -1))
        return luaL_error(L, "sim.sample: the point's coordinate %d is not a number", a + 1);
      pt[a] = lua_tonumber(L, -1);
      lua_pop(L, 1);
    }
    next = 3;
  } else {
    pt[0] = luaL_checknumber(L, 2);
    pt[1] = luaL_checknumber(L, 3);
  }
  for (int a = 0; a < ncoord; ++a)
    if (!isfinite(pt[a]))
      return luaL_error(L, "sim.sample: the point's coordinate %d is %f, not a finite number",
                        a + 1, pt[a]);
  int comp = (int)luaL_optinteger(L, next, 1) - 1;
  const char *how = luaL_optstring(L, next + 1, "shepard");
  const int order = strcmp(how, "linear") == 0 ? 1 : strcmp(how, "shepard") == 0 ? 0 : -1;
  if (order < 0)
    return luaL_error(L, "sim.sample: interpolation must be \"shepard\" or \"linear\", not \"%s\"",
                      how);
  if (api->sample_many(api->ctx, field, comp, order, 1, ncoord, pt, &v) != CLSPH_OK) {
    char at[96];
    if (ncoord == 3)
      snprintf(at, sizeof at, "(%g, %g, %g)", pt[0], pt[1], pt[2]);
    else
      snprintf(at, sizeof at, "(%g, %g)", pt[0], pt[1]);
    return luaL_error(L, "sim.sample: cannot sample '%s' at %s: %s", field, at, why_of(api));
  }
  lua_pushnumber(L, v);
  return 1;
}

/* t = sim.field(name [, component [, kind]]): the particles of a kind (fluid unless
 * given; "all"), t.x, t.y and t.value, arrays indexed from 1 in the same order. */
static int l_field_values(lua_State *L)
{
  const struct case_sim_api *api = api_of(L);
  const char *field = luaL_checkstring(L, 1);
  int comp = (int)luaL_optinteger(L, 2, 1) - 1;
  int kind = kind_of(L, 3);
  size_t n = 0;
  double *xy = NULL, *v = NULL;
  if (api->field_values == NULL ||
      api->field_values(api->ctx, field, comp, kind, &n, &xy, &v) != CLSPH_OK)
    return luaL_error(L, "sim.field: no values of '%s' component %d: %s", field, comp + 1,
                      why_of(api));
  lua_createtable(L, 0, 4);
  const char *names[] = {"x", "y", "z", "value"}; /* z: 0 in 2-D */
  for (int c = 0; c < 4; ++c) {
    lua_createtable(L, (int)n, 0);
    for (size_t i = 0; i < n; ++i) {
      lua_pushnumber(L, c < 3 ? xy[3 * i + (size_t)c] : v[i]);
      lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    lua_setfield(L, -2, names[c]);
  }
  free(xy);
  free(v);
  return 1;
}

/* f = sim.force(group [, since]): the force of the fluid on a wall group (N/m), the mean over
 * the outputs at t >= since, or the last output: f.x, f.y (total), f.pressure_x, f.pressure_y,
 * f.viscous_x, f.viscous_y, f.samples. */
static int l_force_metric(lua_State *L)
{
  static const char *const names[] = {"x",         "y",         "pressure_x", "pressure_y",
                                      "viscous_x", "viscous_y", "torque"};
  const struct case_sim_api *api = api_of(L);
  const char *group = luaL_checkstring(L, 1);
  double since = lua_isnoneornil(L, 2) ? -1.0 : luaL_checknumber(L, 2), v[7];
  int samples = 0;
  if (api->force == NULL || api->force(api->ctx, group, since, v, &samples) != CLSPH_OK)
    return luaL_error(L, "sim.force: %s", why_of(api));
  lua_createtable(L, 0, 8);
  for (int k = 0; k < 7; ++k) {
    lua_pushnumber(L, v[k]);
    lua_setfield(L, -2, names[k]);
  }
  lua_pushinteger(L, samples);
  lua_setfield(L, -2, "samples");
  return 1;
}

/* t = sim.force_history(group [, since]): the recorded total force of a wall group at each row
 * with t >= since (all rows without it): arrays t.time, t.x, t.y, t.torque indexed from 1. */
static int l_force_history(lua_State *L)
{
  const struct case_sim_api *api = api_of(L);
  const char *group = luaL_checkstring(L, 1);
  double since = lua_isnoneornil(L, 2) ? -(double)INFINITY : luaL_checknumber(L, 2), *rows = NULL;
  size_t n = 0;
  if (api->force_history == NULL ||
      api->force_history(api->ctx, group, since, &n, &rows) != CLSPH_OK)
    return luaL_error(L, "sim.force_history: %s", why_of(api));
  static const char *const names[] = {"time", "x", "y", "torque"};
  lua_createtable(L, 0, 4);
  for (int c = 0; c < 4; ++c) {
    lua_createtable(L, (int)n, 0);
    for (size_t r = 0; r < n; ++r) {
      lua_pushnumber(L, rows[4 * r + (size_t)c]);
      lua_rawseti(L, -2, (lua_Integer)r + 1);
    }
    lua_setfield(L, -2, names[c]);
  }
  free(rows);
  return 1;
}

/* Array `idx` of the Lua table at stack index `idx`, as doubles in a userdata pushed on the stack
 * (collected with it, also when an error unwinds). */
static size_t number_array(lua_State *L, int idx, const char *what, double **out)
{
  luaL_checktype(L, idx, LUA_TTABLE);
  const size_t n = (size_t)lua_rawlen(L, idx);
  double *v = lua_newuserdatauv(L, (n + 1) * sizeof *v, 0);
  for (size_t k = 0; k < n; ++k) {
    lua_rawgeti(L, idx, (lua_Integer)k + 1);
    if (!lua_isnumber(L, -1))
      return (size_t)luaL_error(L, "sim.spectrum_peak: %s[%d] is not a number", what, (int)k + 1);
    v[k] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  *out = v;
  return n;
}

/* p = sim.spectrum_peak(times, values [, f_lo [, f_hi]]): the dominant frequency of a sampled
 * signal (spectrum.h): p.frequency, p.amplitude, p.median (the spectrum's noise floor), p.mean. */
static int l_spectrum_peak(lua_State *L)
{
  double *t = NULL, *y = NULL;
  const double lo = luaL_optnumber(L, 3, 0.0), hi = luaL_optnumber(L, 4, 0.0);
  const size_t n = number_array(L, 1, "times", &t);
  const size_t m = number_array(L, 2, "values", &y);
  struct spectrum_peak p;
  const enum clsph_status st = n == m ? spectrum_peak(n, t, y, lo, hi, &p) : CLSPH_E_INPUT;
  if (n != m) return luaL_error(L, "sim.spectrum_peak: %d times but %d values", (int)n, (int)m);
  if (st != CLSPH_OK) return luaL_error(L, "sim.spectrum_peak: %s", clsph_status_str(st));
  lua_createtable(L, 0, 4);
  lua_pushnumber(L, p.frequency);
  lua_setfield(L, -2, "frequency");
  lua_pushnumber(L, p.amplitude);
  lua_setfield(L, -2, "amplitude");
  lua_pushnumber(L, p.median);
  lua_setfield(L, -2, "median");
  lua_pushnumber(L, p.mean);
  lua_setfield(L, -2, "mean");
  return 1;
}

/* Free what read_columns_text made for n rows (text may be NULL). */
static void reference_free(int ncol, int n, double **cols, char ***text)
{
  for (int c = 0; c < ncol; ++c) {
    free(cols[c]);
    cols[c] = NULL;
    if (text == NULL || text[c] == NULL) continue;
    for (int i = 0; i < n; ++i) free(text[c][i]);
    free(text[c]);
    text[c] = NULL;
  }
}

/* Columns names[0 .. ncol) of a reference CSV ('#' comment lines, then a header row) into cols
 * (malloc'd arrays, NaN where a row lacks the column or its cell is no number); returns the number
 * of rows. With `text` not NULL, text[c] is a malloc'd array of the cells that are no number
 * (malloc'd copies; NULL where the cell is one). `fn` names the caller in messages. */
static int read_columns_text(lua_State *L, const char *fn, const char *path, int ncol,
                             const char *const *names, double **cols, char ***text)
{
  FILE *f = fopen(path, "r");
  char line[4096];
  int idx[8], n = 0, cap = 0, header = 0;
  for (int c = 0; c < ncol && c < 8; ++c) {
    idx[c] = -1;
    cols[c] = NULL;
    if (text != NULL) text[c] = NULL;
  }
  if (ncol > 8) return luaL_error(L, "%s: at most 8 columns", fn);
  if (f == NULL) return luaL_error(L, "%s: cannot read %s", fn, path);
  while (fgets(line, sizeof line, f) != NULL) {
    if (line[0] == '#' || line[0] == '\n' || line[0] == '\r') continue;
    char *save = NULL;
    int col = 0;
    if (!header) {
      header = 1;
      for (char *t = strtok_r(line, ",\r\n", &save); t != NULL;
           t = strtok_r(NULL, ",\r\n", &save), ++col)
        for (int c = 0; c < ncol; ++c)
          if (strcmp(t, names[c]) == 0) idx[c] = col;
      for (int c = 0; c < ncol; ++c)
        if (idx[c] < 0) {
          fclose(f);
          return luaL_error(L, "%s: %s has no column '%s'", fn, path, names[c]);
        }
      continue;
    }
    if (n == cap) {
      cap = cap ? 2 * cap : 32;
      for (int c = 0; c < ncol; ++c) {
        double *a = realloc(cols[c], (size_t)cap * sizeof *a);
        char **b = text != NULL ? realloc(text[c], (size_t)cap * sizeof *b) : NULL;
        if (a != NULL) cols[c] = a;
        if (b != NULL) text[c] = b;
        if (a == NULL || (text != NULL && b == NULL)) {
          reference_free(ncol, n, cols, text);
          fclose(f);
          return luaL_error(L, "out of memory");
        }
      }
    }
    for (int c = 0; c < ncol; ++c) {
      cols[c][n] = NAN;
      if (text != NULL) text[c][n] = NULL;
    }
    for (char *t = strtok_r(line, ",\r\n", &save); t != NULL;
         t = strtok_r(NULL, ",\r\n", &save), ++col)
      for (int c = 0; c < ncol; ++c) {
        if (col != idx[c]) continue;
        char *end = NULL;
        const double v = strtod(t, &end);
        while (end != NULL && (*end == ' ' || *end == '\t')) ++end;
        if (end != t && *end == '\0') {
          cols[c][n] = v;
        } else if (text != NULL) {
          text[c][n] = strdup(t);
          if (text[c][n] == NULL) {
            reference_free(ncol, n + 1, cols, text);
            fclose(f);
            return luaL_error(L, "out of memory");
          }
        }
      }
    ++n;
  }
  fclose(f);
  return n;
}

static int read_columns(lua_State *L, const char *fn, const char *path, int ncol,
                        const char *const *names, double **cols)
{
  return read_columns_text(L, fn, path, ncol, names, cols, NULL);
}

/* Columns `coord` and `value` of a reference CSV (read_columns). */
static int read_reference(lua_State *L, const char *path, const char *coord, const char *value,
                          double **xs, double **vs)
{
  const char *names[] = {coord, value};
  double *cols[2];
  const int n = read_columns(L, "profile_error", path, 2, names, cols);
  *xs = cols[0];
  *vs = cols[1];
  return n;
}

/* A reference file's path: as given when it opens from the working folder, else under the source
 * tree (tests/data/... from anywhere). */
static void reference_path(const char *file, char *path, size_t size)
{
  snprintf(path, size, "%s", file);
  FILE *probe = fopen(path, "r");
  if (probe == NULL)
    snprintf(path, size, "%s/%s", CLSPH_SOURCE_DIR, file);
  else
    fclose(probe);
}

/* t = sim.reference(csv, column, ...): columns of a reference CSV ('#' comment lines, a header
 * row; the path as for profile_error) as arrays t[column], indexed from 1, one entry per row: a
 * number, or the cell's text where it is no number. */
static int l_reference(lua_State *L)
{
  const char *file = luaL_checkstring(L, 1);
  const int ncol = lua_gettop(L) - 1;
  const char *names[8];
  double *cols[8];
  char path[2048];
  if (ncol < 1 || ncol > 8) return luaL_error(L, "reference: name 1 to 8 columns of %s", file);
  for (int c = 0; c < ncol; ++c) names[c] = luaL_checkstring(L, c + 2);
  reference_path(file, path, sizeof path);
  char **text[8];
  const int n = read_columns_text(L, "reference", path, ncol, names, cols, text);
  lua_createtable(L, 0, ncol);
  for (int c = 0; c < ncol; ++c) {
    lua_createtable(L, n, 0);
    for (int i = 0; i < n; ++i) {
      if (text[c][i] != NULL)
        lua_pushstring(L, text[c][i]); /* a cell that is no number: its text */
      else
        lua_pushnumber(L, cols[c][i]);
      lua_rawseti(L, -2, i + 1);
    }
    lua_setfield(L, -2, names[c]);
  }
  reference_free(ncol, n, cols, text);
  return 1;
}

/* rms, max = sim.profile_error{ field =, component =, csv =, coordinate =, value =,
 *                               x = (or y =), z = , scale = , skip_walls = true,
 *                               interpolation = "shepard" }
 * Samples the field along the line x = const (coordinate y) or y = const (coordinate x), in the
 * plane z = const in 3-D (z = is what makes the points 3-D), at the reference points and returns
 * the RMS and largest deviation divided by scale; points on the walls (coordinate 0 or 1 of the
 * reference) are skipped when skip_walls; interpolation "linear" samples by first-order moving
 * least squares (sim_sample). */
static int l_profile_error(lua_State *L)
{
  const struct case_sim_api *api = api_of(L);
  luaL_checktype(L, 1, LUA_TTABLE);
  lua_getfield(L, 1, "field");
  const char *field = luaL_checkstring(L, -1);
  lua_getfield(L, 1, "csv");
  const char *csv = luaL_checkstring(L, -1);
  lua_getfield(L, 1, "coordinate");
  const char *coord = luaL_checkstring(L, -1);
  lua_getfield(L, 1, "value");
  const char *value = luaL_checkstring(L, -1);
  lua_getfield(L, 1, "component");
  int comp = (int)luaL_optinteger(L, -1, 1) - 1;
  lua_getfield(L, 1, "scale");
  double scale = luaL_optnumber(L, -1, 1.0);
  lua_getfield(L, 1, "x");
  int along_y = !lua_isnil(L, -1);
  double at = along_y ? luaL_checknumber(L, -1) : 0.0;
  lua_getfield(L, 1, "y");
  if (!along_y) at = luaL_checknumber(L, -1);
  lua_getfield(L, 1, "z");
  const int nc = lua_isnil(L, -1) ? 2 : 3;
  const double zat = nc == 3 ? luaL_checknumber(L, -1) : 0.0;
  if (!isfinite(at) || !isfinite(zat))
    return luaL_error(L, "profile_error: the line's %s = %f is not a finite number",
                      !isfinite(at) ? (along_y ? "x" : "y") : "z", !isfinite(at) ? at : zat);
  lua_getfield(L, 1, "skip_walls");
  int skip = lua_isnil(L, -1) || lua_toboolean(L, -1);
  const int order = get_choice(L, 1, "profile_error", "interpolation", interpolations, 0);
  char path[2048];
  reference_path(csv, path, sizeof path);
  double *xs = NULL, *vs = NULL;
  int n = read_reference(L, path, coord, value, &xs, &vs);
  double *xy = malloc(3 * (size_t)(n + 1) * sizeof *xy),
         *got = malloc((size_t)(n + 1) * sizeof *got);
  int m = 0;
  for (int k = 0; k < n && xy != NULL; ++k) {
    if (skip && (xs[k] <= 0.0 || xs[k] >= 1.0)) continue;
    xy[nc * m] = along_y ? at : xs[k];
    xy[nc * m + 1] = along_y ? xs[k] : at;
    if (nc == 3) xy[3 * m + 2] = zat;
    vs[m] = vs[k];
    ++m;
  }
  if (xy == NULL || got == NULL || m == 0 ||
      api->sample_many(api->ctx, field, comp, order, m, nc, xy, got) != CLSPH_OK) {
    free(xs);
    free(vs);
    free(xy);
    free(got);
    return luaL_error(L, "profile_error: cannot sample '%s' at the points of %s: %s", field, path,
                      xy == NULL || got == NULL ? "out of memory"
                      : m == 0                  ? "none of them is inside"
                                                : why_of(api));
  }
  double ss = 0.0, mx = 0.0;
  for (int k = 0; k < m; ++k) {
    double d = fabs(got[k] - vs[k]) / scale;
    ss += d * d;
    mx = fmax(mx, d);
  }
  free(xs);
  free(vs);
  free(xy);
  free(got);
  lua_pushnumber(L, sqrt(ss / m));
  lua_pushnumber(L, mx);
  return 2;
}

/* t = sim.profile(name, time): the profile line `name` as recorded at the output nearest to
 * `time` (profile_<name>.csv of the output folder): t.time (the output's time) and one array per
 * column, t.s, t.x, t.y, t.vel_x, ..., indexed from 1 along the line. */
static int l_profile_at(lua_State *L)
{
  const struct case_sim_api *api = api_of(L);
  const char *name = luaL_checkstring(L, 1);
  const double want = luaL_checknumber(L, 2);
  char path[2048], line[8192], head[8192];
  if (api->dir == NULL) return luaL_error(L, "sim.profile: the run has no output folder");
  snprintf(path, sizeof path, "%s/profile_%s.csv", api->dir, name);
  FILE *f = fopen(path, "r");
  if (f == NULL) return luaL_error(L, "sim.profile: cannot read %s (no profile '%s'?)", path, name);
  /* pass 1: the recorded time nearest to `want` */
  double best = NAN;
  if (fgets(head, sizeof head, f) == NULL) {
    fclose(f);
    return luaL_error(L, "sim.profile: %s is empty", path);
  }
  while (fgets(line, sizeof line, f) != NULL) {
    double t = strtod(line, NULL);
    if (isnan(best) || fabs(t - want) < fabs(best - want)) best = t;
  }
  if (isnan(best)) {
    fclose(f);
    return luaL_error(L, "sim.profile: %s has no rows", path);
  }
  /* pass 2: the rows at that time, one Lua array per column */
  char *cols[64];
  int nc = 0;
  char *save = NULL;
  for (char *t = strtok_r(head, ",\r\n", &save); t != NULL && nc < 64;
       t = strtok_r(NULL, ",\r\n", &save))
    cols[nc++] = t;
  lua_createtable(L, 0, nc + 1);
  lua_pushnumber(L, best);
  lua_setfield(L, -2, "time");
  for (int c = 1; c < nc; ++c) {
    lua_newtable(L);
    lua_setfield(L, -2, cols[c]);
  }
  rewind(f);
  if (fgets(line, sizeof line, f) == NULL) line[0] = '\0'; /* the header again */
  int row = 0;
  while (fgets(line, sizeof line, f) != NULL) {
    char *end = NULL;
    if (strtod(line, &end) != best) continue;
    ++row;
    for (int c = 1; c < nc && *end == ','; ++c) {
      double v = strtod(end + 1, &end);
      lua_getfield(L, -1, cols[c]);
      lua_pushnumber(L, v);
      lua_rawseti(L, -2, row);
      lua_pop(L, 1);
    }
  }
  fclose(f);
  return 1;
}

/* The table `sim` that metrics() and sample() receive, on the stack. */
static void push_sim(lua_State *L, const struct case_sim_api *api)
{
  lua_newtable(L);
  lua_pushnumber(L, api->time);
  lua_setfield(L, -2, "time");
  lua_pushinteger(L, api->steps);
  lua_setfield(L, -2, "steps");
  lua_pushnumber(L, api->particles);
  lua_setfield(L, -2, "particles");
  lua_pushinteger(L, api->wall_steps);
  lua_setfield(L, -2, "wall_crossing_steps");
  lua_pushinteger(L, api->wall_most);
  lua_setfield(L, -2, "wall_crossings_most");
  lua_pushinteger(L, api->escaped);
  lua_setfield(L, -2, "escaped");
  lua_createtable(L, 3, 0); /* the body force now: {x, y, z}, x the flow-rate control's */
  for (int k = 0; k < 3; ++k) {
    lua_pushnumber(L, api->body[k]);
    lua_rawseti(L, -2, k + 1);
  }
  lua_setfield(L, -2, "body_force");
  if (api->stopped != NULL) { /* nil for a run that reached its end */
    lua_pushstring(L, api->stopped);
    lua_setfield(L, -2, "stopped");
  }
  static const luaL_Reg fns[] = {{"min", l_min},
                                 {"max", l_max},
                                 {"mean", l_mean},
                                 {"sample", l_sample},
                                 {"probe", l_probe_now},
                                 {"reference", l_reference},
                                 {"field", l_field_values},
                                 {"force", l_force_metric},
                                 {"force_history", l_force_history},
                                 {"series", l_series},
                                 {"spectrum_peak", l_spectrum_peak},
                                 {"profile_error", l_profile_error},
                                 {"profile", l_profile_at}};
  for (size_t i = 0; i < sizeof fns / sizeof *fns; ++i) {
    lua_pushlightuserdata(L, (void *)(size_t)api);
    lua_pushcclosure(L, fns[i].func, 1);
    lua_setfield(L, -2, fns[i].name);
  }
}

/* The global function `name` of the script on the stack (raw access: a metamethod the script set
 * on _G runs only inside the sandbox's calls); returns whether there is one. */
static int push_hook(lua_State *L, const char *name)
{
  lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_pushstring(L, name);
  lua_rawget(L, -2);
  lua_remove(L, -2);
  return !lua_isnil(L, -1);
}

/* Call the hook on the stack with the table `sim`: its result, a table of name = number, is left
 * on the stack. */
static enum clsph_status call_hook(struct case_script *cs, const char *phase,
                                   const struct case_sim_api *api)
{
  enum clsph_status st = CLSPH_OK;
  lua_State *L = cs->L;
  CLSPH_CHECK(lua_isfunction(L, -1), CLSPH_E_INPUT, "%s: %.*s must be a function", cs->sb.path,
              (int)(strlen(phase) - 2), phase);
  push_sim(L, api);
  CLSPH_TRY(sandbox_call(&cs->sb, 1, 1, phase));
  CLSPH_CHECK(lua_istable(L, -1), CLSPH_E_INPUT, "%s: %s must return a table of name = number",
              cs->sb.path, phase);
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    CLSPH_CHECK(lua_type(L, -2) == LUA_TSTRING && lua_type(L, -1) == LUA_TNUMBER, CLSPH_E_INPUT,
                "%s: %s: every entry must be name = number (%s = %s)", cs->sb.path, phase,
                lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : luaL_typename(L, -2),
                luaL_typename(L, -1));
    lua_pop(L, 1);
  }
done:
  return st;
}

enum clsph_status case_metrics(struct case_script *cs, const struct case_sim_api *api,
                               struct cJSON *out)
{
  enum clsph_status st = CLSPH_OK;
  lua_State *L = cs->L;
  int top = lua_gettop(L);
  if (!push_hook(L, "metrics")) goto done;
  CLSPH_TRY(call_hook(cs, "metrics()", api));
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    cJSON_AddNumberToObject(out, lua_tostring(L, -2), lua_tonumber(L, -1));
    lua_pop(L, 1);
  }
done:
  lua_settop(L, top);
  return st;
}

int case_has_sample(const struct case_script *cs)
{
  if (cs == NULL) return 0;
  const int top = lua_gettop(cs->L);
  const int has = push_hook(cs->L, "sample");
  lua_settop(cs->L, top);
  return has;
}

static int cmp_name(const void *a, const void *b)
{
  return strcmp((const char *)a, (const char *)b);
}

enum clsph_status case_sample(struct case_script *cs, const struct case_sim_api *api,
                              struct case_values *v)
{
  enum clsph_status st = CLSPH_OK;
  lua_State *L = cs->L;
  const int top = lua_gettop(L);
  char(*names)[SCENE_NAME] = NULL;
  int n = 0;
  CLSPH_CHECK(push_hook(L, "sample"), CLSPH_E_INPUT, "%s declares no sample(sim)", cs->sb.path);
  CLSPH_TRY(call_hook(cs, "sample()", api));
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    ++n;
    lua_pop(L, 1);
  }
  CLSPH_CHECK(n > 0, CLSPH_E_INPUT, "%s: sample() returned no values", cs->sb.path);
  names = calloc((size_t)n, sizeof *names);
  CLSPH_CHECK(names != NULL, CLSPH_E_NOMEM, "out of memory");
  int k = 0;
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    const char *name = lua_tostring(L, -2);
    CLSPH_CHECK(name[0] != '\0' && strlen(name) < SCENE_NAME && strpbrk(name, ",\"\n\r") == NULL &&
                    strcmp(name, "time") != 0,
                CLSPH_E_INPUT,
                "%s: sample(): '%s' is not a column name (1 to %d characters, no "
                "comma, quote or line break, not 'time')",
                cs->sb.path, name, SCENE_NAME - 1);
    snprintf(names[k++], SCENE_NAME, "%s", name);
    lua_pop(L, 1);
  }
  qsort(names, (size_t)n, sizeof *names, cmp_name);
  if (v->n == 0) { /* the first call: its names are the columns */
    v->values = calloc((size_t)n, sizeof *v->values);
    CLSPH_CHECK(v->values != NULL, CLSPH_E_NOMEM, "out of memory");
    v->names = names;
    names = NULL;
    v->n = n;
  } else {
    int same = n == v->n;
    for (int i = 0; same && i < n; ++i) same = strcmp(names[i], v->names[i]) == 0;
    CLSPH_CHECK(same, CLSPH_E_INPUT,
                "%s: sample() returned other names than at its first call (%d values, then %d): "
                "series.csv has one column per name, so every call must return the same names",
                cs->sb.path, v->n, n);
  }
  for (int i = 0; i < v->n; ++i) {
    lua_pushstring(L, v->names[i]);
    lua_rawget(L, -2); /* raw: a metatable of the script's runs only inside the sandbox */
    v->values[i] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
done:
  free(names);
  lua_settop(L, top);
  return st;
}

void case_values_free(struct case_values *v)
{
  free(v->names);
  free(v->values);
  memset(v, 0, sizeof *v);
}

void case_close(struct case_script *cs)
{
  if (cs == NULL) return;
  if (cs->L != NULL) lua_close(cs->L);
  free(cs);
}
