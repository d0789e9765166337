// Hostile submission: includes the system's account list, hoping the compiler's error message
// shows it. The sandbox that compiles it has no /etc/passwd.
#include </etc/passwd>
#include "pathlab/lab.h"
