/* Mesa 22.3.6 (Debian 12) OSMesa leaks 480 bytes in 5 allocations per context that is
 * created, made current and destroyed, with no Prism code involved. Reproduce:
 *   clang-14 -fsanitize=address osmesa_leak_repro.c -lOSMesa && ./a.out
 * This is why tests/sanitizers/lsan.supp names libOSMesa.so.8. */
#include <GL/osmesa.h>
#include <stdlib.h>
int main(void) {
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    OSMesaContext c = OSMesaCreateContextAttribs(attribs, NULL);
    unsigned char* buf = calloc(64 * 64, 4);
    OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 64, 64);
    OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(c);
    free(buf);
    return 0;
}
