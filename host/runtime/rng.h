/* rng.h: seeded pseudo-random numbers (xoshiro256**), the same sequence on every machine. */
#ifndef CLSPH_RNG_H
#define CLSPH_RNG_H

#include <stdint.h>

struct rng {
  uint64_t s[4];
};

/** @brief Seed the generator (splitmix64 expansion of `seed`). */
void rng_seed(struct rng *r, uint64_t seed);
/** @brief Next 64 random bits. */
uint64_t rng_next(struct rng *r);
/** @brief Uniform double in [0, 1). */
double rng_uniform(struct rng *r);
/** @brief Uniform integer in [0, n). */
uint64_t rng_below(struct rng *r, uint64_t n);

#endif /* CLSPH_RNG_H */
