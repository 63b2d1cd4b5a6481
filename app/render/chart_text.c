/* Plain maths in chart text to PLplot's escape sequences (charts.h). */
#include "charts.h"

#include <ctype.h>
#include <string.h>

static int is_alpha(char c) { return isalpha((unsigned char)c) != 0; }
static int is_alnum(char c) { return isalnum((unsigned char)c) != 0; }

size_t pl_chart_text(const char *in, char *out, size_t n)
{
    size_t o = 0, need = 0;
#define PUT(str)                                                                                   \
    do {                                                                                           \
        const char *s_ = (str);                                                                    \
        size_t l_ = strlen(s_);                                                                    \
        for (size_t k_ = 0; k_ < l_; k_++, need++)                                                 \
            if (o + 1 < n) out[o++] = s_[k_];                                                      \
    } while (0)
    if (!in) in = "";
    size_t len = strlen(in);
    for (size_t i = 0; i < len; i++) {
        char c = in[i];
        char one[2] = {c, 0};
        if (c == '#') {
            PUT("##");
        } else if (c == '<' && in[i + 1] == '=') {
            PUT("\u2264");
            i++;
        } else if (c == '>' && in[i + 1] == '=') {
            PUT("\u2265");
            i++;
        } else if (c == '_' && i > 0 && is_alpha(in[i - 1]) &&
                   (i < 2 || !is_alpha(in[i - 2]) || i < 3 || !is_alpha(in[i - 3]))) {
            /* a subscript after a symbol of one or two letters: T_v, Re_p, v_{out} */
            size_t a = i + 1, b;
            int braced = in[a] == '{';
            if (braced) {
                b = a + 1;
                while (b < len && in[b] != '}') b++;
                if (b >= len || b == a + 1) {
                    PUT(one);
                    continue;
                }
                a++;
            } else {
                b = a;
                while (b < len && is_alnum(in[b])) b++;
                if (b == a || b - a > 3) {
                    PUT(one);
                    continue;
                }
            }
            PUT("#d");
            for (size_t k = a; k < b; k++) {
                char s[2] = {in[k], 0};
                PUT(in[k] == '#' ? "##" : s);
            }
            PUT("#u");
            i = braced ? b : b - 1;
        } else if (c == '^' && i > 0 && is_alnum(in[i - 1]) &&
                   (isdigit((unsigned char)in[i + 1]) ||
                    (in[i + 1] == '-' && isdigit((unsigned char)in[i + 2])))) {
            /* an exponent: m^2, s^-1 */
            size_t b = i + 1;
            if (in[b] == '-') b++;
            while (b < len && isdigit((unsigned char)in[b])) b++;
            PUT("#u");
            for (size_t k = i + 1; k < b; k++) {
                char s[2] = {in[k] == '-' ? 0 : in[k], 0};
                PUT(in[k] == '-' ? "\u2212" : s);
            }
            PUT("#d");
            i = b - 1;
        } else {
            PUT(one);
        }
    }
    if (n > 0) out[o < n ? o : n - 1] = 0;
#undef PUT
    return need;
}
