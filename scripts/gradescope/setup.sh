#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image: autograder.zip
# (make gradescope) is unpacked in /autograder/source, this script sits at its root. It installs
# PathLab's packages with the kit's own script and builds the grader (no tests) in
# /autograder/source/build; run_autograder then grades each submission with it.
set -euo pipefail
source=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
cd "$source"

# Zip files do not always keep Unix permissions. The grader's sandbox runs as an unprivileged
# user, which must read the sources it binds (the solutions are only ever compiled there, and
# submitted code runs where they are not bound).
chmod -R a+rX,go-w "$source"
chmod 755 "$source/.." "$source"
chmod +x setup.sh run_autograder scripts/*.sh
# Gradescope copies run_autograder to /autograder when it builds the image.
if [ -e ../run_autograder ]; then chmod 755 ../run_autograder; fi

bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPATHLAB_BUILD_TESTS=OFF
cmake --build build --target grader
# No hidden scene of the instructor's: variants of the public scenes, drawn here from a seed no
# student sees, unless the rubric asks for none (hidden_scenes.variants 0), as a batch makes them.
if ! ls grader/hidden_scenes/*.ecs >/dev/null 2>&1 &&
   [ "$(python3 -c 'import json; print(json.load(open("grader/rubric.json")).get("hidden_scenes", {}).get("variants", 1))')" != 0 ]; then
    build/grader make-variants grader/hidden_scenes
fi
# The hidden scenes' references, measured once here rather than for every submission.
if ls grader/hidden_scenes/*.ecs >/dev/null 2>&1; then
    build/grader make-references --only-hidden
fi
# The sandbox compiles a submission with the headers the build generated too (build/generated/).
chmod -R a+rX build
echo "setup.sh: PathLab's grader is built in $source/build"
