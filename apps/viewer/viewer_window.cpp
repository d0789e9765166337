#include "viewer_window.h"

#include <cstdio>
#include <cstdlib>

int runViewerWindow(const pathlab::RenderOptions&) {
    std::fprintf(stderr, "viewer: the interactive window is not part of this build yet; render "
                         "headless with -o FILE.png (see viewer --help)\n");
    return 2;
}
