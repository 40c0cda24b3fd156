/* status.c: names of the result codes. */
#include "status.h"

#include <stddef.h>

const char *clsph_status_str(enum clsph_status st)
{
  static const char *const names[] = {
      [CLSPH_OK] = "CLSPH_OK",
      [CLSPH_E_NOMEM] = "CLSPH_E_NOMEM",
      [CLSPH_E_IO] = "CLSPH_E_IO",
      [CLSPH_E_INPUT] = "CLSPH_E_INPUT",
      [CLSPH_E_CL] = "CLSPH_E_CL",
      [CLSPH_E_BUILD] = "CLSPH_E_BUILD",
      [CLSPH_E_NOFP64] = "CLSPH_E_NOFP64",
      [CLSPH_E_UNSUPPORTED] = "CLSPH_E_UNSUPPORTED",
      [CLSPH_E_NODEVICE] = "CLSPH_E_NODEVICE",
      [CLSPH_E_BLOWUP] = "CLSPH_E_BLOWUP",
      [CLSPH_E_INTERRUPTED] = "CLSPH_E_INTERRUPTED",
  };
  if ((unsigned)st < sizeof names / sizeof *names && names[st] != NULL) return names[st];
  return "CLSPH_E_UNKNOWN";
}
