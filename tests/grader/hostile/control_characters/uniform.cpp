// Hostile submission: a compiler error whose message holds an escape sequence (a terminal title,
// a wiped line) and a forged verdict. The compiler's messages reach the feedback and the logs
// with every control byte written as \xNN.
#include "pathlab/lab.h"

#error ]0;PWNED-TITLE[2Kinjected: uniform compiled fine, 10 / 10
