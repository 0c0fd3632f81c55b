/* Minimal test helpers: CHECK records a failure and continues; main returns the count. */
#ifndef TF_H
#define TF_H
#include <stdio.h>
#include <string.h>
static int tf_failures;
static int tf_checks;
#define CHECK(c)                                                              \
    do {                                                                      \
        tf_checks++;                                                          \
        if (!(c)) {                                                           \
            tf_failures++;                                                    \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #c); \
        }                                                                     \
    } while (0)
#define CHECK_EQ(a, b)                                                                              \
    do {                                                                                            \
        long long tf_a = (long long)(a), tf_b = (long long)(b);                                     \
        tf_checks++;                                                                                \
        if (tf_a != tf_b) {                                                                         \
            tf_failures++;                                                                          \
            fprintf(stderr, "%s:%d: CHECK_EQ failed: %s = %lld, %s = %lld\n", __FILE__, __LINE__, #a, \
                    tf_a, #b, tf_b);                                                                \
        }                                                                                           \
    } while (0)
#define TF_RUN(fn)                         \
    do {                                   \
        int tf_before = tf_failures;       \
        fn();                              \
        printf("%s %s\n", tf_before == tf_failures ? "ok  " : "FAIL", #fn); \
    } while (0)
#define TF_END()                                                              \
    do {                                                                      \
        printf("%d checks, %d failures\n", tf_checks, tf_failures);           \
        return tf_failures == 0 ? 0 : 1;                                      \
    } while (0)
#endif
