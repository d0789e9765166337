// Hostile submission: includes an endless device. Stopped by the compiler's time and memory
// limits.
#include </dev/urandom>
