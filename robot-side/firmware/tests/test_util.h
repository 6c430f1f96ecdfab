/* Minimal test harness for the firmware's C tests (no framework on the board side). */
#ifndef TEST_UTIL_H
#define TEST_UTIL_H
#include <stdio.h>
#include <stdlib.h>

extern int g_test_failures;
extern int g_log_lines;

#define CHECK(cond)                                                                   \
    do {                                                                              \
        if (!(cond)) {                                                                \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
            g_test_failures++;                                                        \
        }                                                                             \
    } while (0)

#define CHECK_EQ(a, b)                                                                           \
    do {                                                                                         \
        long long _a = (long long)(a), _b = (long long)(b);                                      \
        if (_a != _b) {                                                                          \
            fprintf(stderr, "%s:%d: CHECK_EQ failed: %s == %lld, %s == %lld\n", __FILE__, __LINE__, \
                    #a, _a, #b, _b);                                                             \
            g_test_failures++;                                                                   \
        }                                                                                        \
    } while (0)

#define TEST_DONE()                                                        \
    do {                                                                   \
        if (g_test_failures) {                                             \
            fprintf(stderr, "%d check(s) failed\n", g_test_failures);      \
            return 1;                                                      \
        }                                                                  \
        printf("all checks passed\n");                                     \
        return 0;                                                          \
    } while (0)

#endif
