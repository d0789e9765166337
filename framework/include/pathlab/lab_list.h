#pragma once
/// The labs, in the order the handouts teach them: the one list that the Lab enum, the labs'
/// names and namespaces, the tables of their pathTrace functions, the build (CMakeLists.txt
/// reads the names from the lines below) and the viewer's number keys all follow. A new lab is
/// one line here plus its files (docs/architecture.md: Adding a lab).
///
/// PATHLAB_LAB(name, Enumerator, depthLimited): `name` is the lab's file (labs/NAME.cpp), its
/// namespace (pathlab::NAME) and its --lab name; `depthLimited` says whether it stops at
/// maxDepth, estimating the depth-limited image (labs 1–3), or is unbiased (lab 4).
/// Keep one lab per line: CMake reads them line by line.
#define PATHLAB_FOR_EACH_LAB(PATHLAB_LAB)                                                          \
    PATHLAB_LAB(branching, Branching, true)                                                        \
    PATHLAB_LAB(uniform, Uniform, true)                                                            \
    PATHLAB_LAB(importance, Importance, true)                                                      \
    PATHLAB_LAB(roulette, Roulette, false)
