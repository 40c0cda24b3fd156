/* str.h: strings sized to fit (paths built from a user's --out have no fixed limit). */
#ifndef CLSPH_STR_H
#define CLSPH_STR_H

#include "log.h"

/** @brief A malloc'd copy of a formatted string, or NULL when out of memory. */
char *str_printf(const char *fmt, ...) LOG_PRINTF(1, 2);

#endif /* CLSPH_STR_H */
