/* The three functions of libsodium's sodium/utils.c and randombytes.c that the vendored files
 * refer to, for a build without the rest of libsodium (a Cortex-M3 has no mmap, mlock or
 * /dev/urandom). Not libsodium's file: written for Touchline (see SOURCE); the two bodies are
 * libsodium 1.0.18's portable branches (no memset_s, explicit_bzero or weak symbols on a
 * bare-metal newlib), copied. */
#include <stdlib.h>

#include "randombytes.h"
#include "utils.h"

void
sodium_memzero(void * const pnt, const size_t len)
{
    volatile unsigned char *volatile pnt_ =
        (volatile unsigned char *volatile) pnt;
    size_t i = (size_t) 0U;

    while (i < len) {
        pnt_[i++] = 0U;
    }
}

int
sodium_memcmp(const void *const b1_, const void *const b2_, size_t len)
{
    const volatile unsigned char *volatile b1 =
        (const volatile unsigned char *volatile) b1_;
    const volatile unsigned char *volatile b2 =
        (const volatile unsigned char *volatile) b2_;
    size_t                 i;
    volatile unsigned char d = 0U;

    for (i = 0U; i < len; i++) {
        d |= b1[i] ^ b2[i];
    }
    return (1 & ((d - 1) >> 8)) - 1;
}

/* Only crypto_auth_hmacsha256_keygen refers to it, which the firmware never calls: a robot
 * never makes a key (the console does, `touchline keys new`), so there is no random source
 * here, and a call stops the program rather than hand out a predictable key. */
void
randombytes_buf(void * const buf, const size_t size)
{
    (void) buf;
    (void) size;
    abort();
}
