#include <stdio.h>
#include <stdint.h>
#include "test_util.h"

int g_test_failures;
int g_log_lines;

/* The platform's log hook, counted so tests can assert that bad input was reported. */
void fw_log(const char *what, const char *detail, int32_t value)
{
    g_log_lines++;
    if (getenv("FW_TEST_VERBOSE")) fprintf(stderr, "log: %s %s (%ld)\n", what, detail ? detail : "", (long)value);
}
