/* Preloaded in the sanitizer tier (scripts/run-sanitizer-tests.sh): makes dlclose() a
 * no-op so that the Mesa drivers EGL loads and unloads stay mapped until LeakSanitizer
 * reports at exit. Without it their leaks show as "<unknown module>", which no
 * suppression can name; with it tests/sanitizers/lsan.supp can name the Mesa library.
 * Nothing else changes: a library stays loaded a little longer. */
int dlclose(void* handle) {
    (void)handle;
    return 0;
}
