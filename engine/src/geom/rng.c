/* xoshiro256** seeded by splitmix64 (Blackman & Vigna, "Scrambled linear pseudorandom
 * number generators", 2018; written here from the published recurrences). Deterministic
 * and platform independent: only 64-bit integer arithmetic. */
#include "porelab/shapes.h"

static uint64_t splitmix64(uint64_t *x) {
    uint64_t z = (*x += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static inline uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

void pl_rng_seed(pl_rng *rng, uint64_t seed) {
    uint64_t x = seed;
    for (int i = 0; i < 4; i++) rng->s[i] = splitmix64(&x);
    /* splitmix64 never yields four zero words in a row, so the state is valid. */
}

uint64_t pl_rng_next(pl_rng *rng) {
    uint64_t *s = rng->s;
    const uint64_t result = rotl(s[1] * 5, 7) * 9;
    const uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return result;
}

double pl_rng_uniform(pl_rng *rng) {
    return (double)(pl_rng_next(rng) >> 11) * 0x1.0p-53;
}

double pl_rng_range(pl_rng *rng, double lo, double hi) {
    return lo + (hi - lo) * pl_rng_uniform(rng);
}

int pl_rng_int(pl_rng *rng, int lo, int hi) {
    if (hi <= lo) return lo;
    const uint64_t span = (uint64_t)((int64_t)hi - (int64_t)lo) + 1u;
    /* Rejection sampling: discard the top partial block so every value is equally likely. */
    const uint64_t limit = UINT64_MAX - (UINT64_MAX % span) - 1u;
    uint64_t x;
    do x = pl_rng_next(rng); while (x > limit);
    return (int)((int64_t)lo + (int64_t)(x % span));
}
