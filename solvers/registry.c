/* registry.c: the schemes clsph knows, by name. */
#include <stdio.h>
#include <string.h>

#include "scheme.h"

extern const struct scheme_ops scheme_none;
extern const struct scheme_ops scheme_ballistic;
extern const struct scheme_ops scheme_isph_usaw;
extern const struct scheme_ops scheme_wcsph_usaw;
extern const struct scheme_ops scheme_isph_rotational;

static const struct scheme_ops *const schemes[] = {&scheme_none, &scheme_ballistic,
                                                   &scheme_isph_usaw, &scheme_wcsph_usaw,
                                                   &scheme_isph_rotational};

enum clsph_status scheme_find(const char *name, const struct scheme_ops **out)
{
  enum clsph_status st = CLSPH_OK;
  char list[512];
  size_t used = 0;
  list[0] = '\0';
  for (size_t i = 0; i < sizeof schemes / sizeof *schemes; ++i) {
    if (strcmp(schemes[i]->name, name) == 0) {
      *out = schemes[i];
      goto done;
    }
    used +=
        (size_t)snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "", schemes[i]->name);
  }
  CLSPH_CHECK(0, CLSPH_E_INPUT, "unknown scheme '%s'; schemes: %s", name, list);
done:
  return st;
}

void scheme_print_list(void)
{
  for (size_t i = 0; i < sizeof schemes / sizeof *schemes; ++i)
    printf("  %-18s %s\n", schemes[i]->name, schemes[i]->summary);
}
