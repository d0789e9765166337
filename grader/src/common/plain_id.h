#pragma once
/// A student's id as every part of the grader spells it: a submission's folder or archive name,
/// `grader student-variants`' ids, the late policy's extensions and Gradescope's sid or email
/// (scripts/gradescope/run_autograder spells them alike). Letters, digits and . _ - are kept, any
/// other byte becomes _ ("ada@uni.edu" is "ada_uni.edu"), and an id that would be empty or begin
/// with a dot is prefixed with "submission".

#include <string>

namespace pathlab::grader {

std::string plainId(const std::string& name);

} // namespace pathlab::grader
