/* spell.c: suggestions for misspelt names (case keys, parameters, schemes). */
#include "spell.h"

#include <stdio.h>
#include <string.h>

int spell_distance(const char *a, const char *b)
{
  size_t la = strlen(a), lb = strlen(b);
  if (la > 63 || lb > 63) return 99;
  int d[64][64];
  for (size_t i = 0; i <= la; ++i) d[i][0] = (int)i;
  for (size_t j = 0; j <= lb; ++j) d[0][j] = (int)j;
  for (size_t i = 1; i <= la; ++i) {
    for (size_t j = 1; j <= lb; ++j) {
      int sub = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
      int del = d[i - 1][j] + 1, ins = d[i][j - 1] + 1;
      d[i][j] = sub < del ? (sub < ins ? sub : ins) : (del < ins ? del : ins);
    }
  }
  return d[la][lb];
}

int spell_nearest(const char *word, const char *const *known)
{
  int best = -1, bd = 99;
  for (int i = 0; known[i] != NULL; ++i) {
    int d = spell_distance(word, known[i]);
    if (d < bd) {
      bd = d;
      best = i;
    }
  }
  return bd <= 3 ? best : -1;
}

void spell_suggest(const char *word, const char *const *known, char *buf, size_t size)
{
  const int best = spell_nearest(word, known);
  if (best >= 0) {
    snprintf(buf, size, "; did you mean '%s'?", known[best]);
    return;
  }
  size_t used = (size_t)snprintf(buf, size, "; known:");
  for (int i = 0; known[i] != NULL && used < size; ++i)
    used += (size_t)snprintf(buf + used, size - used, " %s", known[i]);
}
