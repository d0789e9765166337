// grader student-variants ID... --out DIR: each student's own variant folder (the rubric's
// variants.per_student; student_variant.h), for the instructor to send to that student alone, so
// that the student's `make grade VARIANT=DIR` grades on the scenes the batch grades them on.
#include "checks/student_variant.h"
#include "commands/commands.h"
#include "common/plain_id.h"

#include "pathlab/support/input_error.h"

#include <cstdio>
#include <filesystem>
#include <map>

namespace pathlab::grader {

namespace {

/// A student's id as a folder name of --out: one plain name, never a path out of it.
void requirePlainId(const std::string& id) {
    if (id.empty() || id == "." || id == ".." || id.find_first_of("/\\") != std::string::npos ||
        id[0] == '.')
        throw InputError("grader student-variants: '" + id +
                         "' is not a student id (a plain name, as a batch's submission folder)");
}

} // namespace

int makeStudentVariants(const Arguments& a, const Rubric& rubric, const std::string& scratch) {
    if (!rubric.variants.perStudent)
        throw InputError(a.rubric +
                         ": variants.per_student is not set: every student grades on the same "
                         "scenes (the instructor guide's Per-student variants says how to set it)");
    // Each id as the batch and Gradescope's run_autograder spell it (ada@uni.edu: ada_uni.edu):
    // the variant is drawn from that spelling. Two ids spelled alike would share a variant.
    std::map<std::string, std::string> spelled;
    for (const std::string& given : a.inputs) {
        requirePlainId(given);
        const std::string id = plainId(given);
        if (const auto [other, isNew] = spelled.try_emplace(id, given); !isNew)
            throw InputError("grader student-variants: '" + other->second + "' and '" + given +
                             "' are both the id '" + id +
                             "' to the grader (letters, digits and . _ - are kept, any other "
                             "character becomes _): they would share a variant");
        if (id != given)
            std::printf("%s: graded as %s (letters, digits and . _ - kept, others as _)\n",
                        given.c_str(), id.c_str());
    }
    const std::string secret = classSecret(rubric.variants);
    const LabRunner solution{a.solutionViewer, Implementation::Solution, {}, {}, {}};
    for (const auto& [id, given] : spelled) {
        const std::string folder = a.out + "/" + id;
        std::filesystem::remove_all(folder);
        const StudentVariant variant = drawStudentVariant(rubric.variants, secret, id);
        const auto scenes =
            writeStudentVariantFolder(rubric, variant, folder, solution, scratch, a.referenceCache);
        std::printf("%s: %s", folder.c_str(), scenes.front().name.c_str());
        for (size_t i = 1; i < scenes.size(); ++i) std::printf(", %s", scenes[i].name.c_str());
        std::printf("\n");
    }
    std::printf("send each student their own folder only: `make grade VARIANT=FOLDER` grades them "
                "on it\n");
    return 0;
}

} // namespace pathlab::grader
