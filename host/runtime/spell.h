/* spell.h: the nearest of a list of names to a misspelt one ("did you mean ...?"). */
#ifndef CLSPH_SPELL_H
#define CLSPH_SPELL_H

#include <stddef.h>

/** @brief Edit (Levenshtein) distance between two names; 99 for names longer than 63. */
int spell_distance(const char *a, const char *b);
/** @brief The index of the name of `known` (NULL-terminated) nearest to `word` within an edit
 *  distance of 3, or −1. */
int spell_nearest(const char *word, const char *const *known);
/** @brief "; did you mean 'x'?" for the nearest of `known`, else "; known: a b c" (cut to fit). */
void spell_suggest(const char *word, const char *const *known, char *buf, size_t size);

#endif /* CLSPH_SPELL_H */
