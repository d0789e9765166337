#include "reports/submission_time.h"

#include "pathlab/render/lab_registry.h"
#include "pathlab/support/parse_number.h"
#include "pathlab/support/input_error.h"

#include <cstdio>
#include <ctime>
#include <fstream>
#include <vector>

namespace pathlab::grader {

SubmissionTimes loadSubmissionTimes(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open the submission times");
    SubmissionTimes times;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        std::vector<std::string> fields;
        for (std::string_view field : splitAt(line, ',')) fields.emplace_back(field);
        const std::optional<long long> seconds =
            fields.size() >= 2 ? parseTime(fields.back()) : std::nullopt;
        // The header: id,submitted_at or id,lab,submitted_at.
        if (number == 1 && !seconds && fields[0] == "id") continue;
        const std::string where = path + ":" + std::to_string(number) + ": ";
        if (!seconds || fields.size() > 3 || fields[0].empty())
            throw InputError(where +
                             "expected id,time or id,lab,time (time as 2026-12-01T23:59:00Z), "
                             "got '" +
                             line + "'");
        const long long at = seconds.value_or(0); // given: checked above
        if (fields.size() == 2) {
            times.whole[fields[0]] = at;
            continue;
        }
        if (!labFromName(fields[1]))
            throw InputError(where + "'" + fields[1] + "' is not a lab (" + labNames(", ") + ")");
        times.byLab[fields[0]][fields[1]] = at;
    }
    return times;
}

} // namespace pathlab::grader
