/* registry.c: the schemes clsph knows, by name. */
#include <stdio.h>
#include <string.h>

#include "scheme.h"
#include "spell.h"

extern const struct scheme_ops scheme_none;
extern const struct scheme_ops scheme_ballistic;
extern const struct scheme_ops scheme_isph_usaw;
extern const struct scheme_ops scheme_wcsph_usaw;
extern const struct scheme_ops scheme_isph_rotational;
extern const struct scheme_ops scheme_wcsph_riemann;
extern const struct scheme_ops scheme_isph_stabilized;

static const struct scheme_ops *const schemes[] = {
    &scheme_none,           &scheme_ballistic,       &scheme_isph_usaw,
    &scheme_wcsph_usaw,     &scheme_isph_rotational, &scheme_wcsph_riemann,
    &scheme_isph_stabilized};

enum clsph_status scheme_find(const char *name, const char *where, const struct scheme_ops **out)
{
  enum clsph_status st = CLSPH_OK;
  enum { N = sizeof schemes / sizeof *schemes };
  const char *names[N + 1];
  char list[512];
  size_t used = 0;
  list[0] = '\0';
  for (size_t i = 0; i < N; ++i) {
    if (strcmp(schemes[i]->name, name) == 0) {
      *out = schemes[i];
      goto done;
    }
    names[i] = schemes[i]->name;
    used += (size_t)snprintf(list + used, used < sizeof list ? sizeof list - used : 0, "%s%s",
                             i ? ", " : "", schemes[i]->name);
  }
  names[N] = NULL;
  const int near = spell_nearest(name, names);
  char hint[96] = "";
  if (near >= 0) snprintf(hint, sizeof hint, "; did you mean '%s'?", names[near]);
  CLSPH_CHECK(0, CLSPH_E_INPUT, "%s%sunknown scheme '%s'%s (schemes: %s)", where ? where : "",
              where ? ": scheme: " : "", name, hint, list);
done:
  return st;
}

void scheme_print_list(void)
{
  for (size_t i = 0; i < sizeof schemes / sizeof *schemes; ++i)
    printf("  %-18s %s\n", schemes[i]->name, schemes[i]->summary);
}
