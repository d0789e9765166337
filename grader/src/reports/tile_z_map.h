#pragma once
/// The correctness check's verdict as a picture: each tile of a scene coloured by the z-score of
/// its mean against the reference, from the statistics the check tests
/// (checks/correctness_check.cpp), for the HTML report. A correct lab's tiles scatter around 0
/// and stay pale; a wrong one's tiles where it is wrong turn saturated red (too bright) or blue
/// (too dark).

#include <string>
#include <vector>

namespace pathlab::grader {

/// The size of z-score at which the colour saturates: a two-sided p of 6e-5. Holm's first
/// threshold over the grading scenes' regions at the rubric's alpha (0.001 over some 300
/// regions: z 4.6) lies just beyond it, so a tile that the check rejects is fully red or blue
/// and one that is pale is far from it.
constexpr double tileZSaturation = 4;

/// The z-score of a two-sided p-value: the standard normal quantile with that two-sided tail,
/// signed like `t`. The check's t has few degrees of freedom (seeds − 1) and so heavy tails; the
/// map shows its p on the normal scale, where a correct lab's tiles fall as ~N(0, 1).
double zScoreOfP(double p, double t);

/// A tile's z-score as the map shows it: of its three channels, the one with the smallest p
/// (`regionT`, `regionP` [region][channel], region 0 the whole image, as the check computes
/// them), on the normal scale. `tile` counts from 0, row by row from the top left.
double tileZ(const std::vector<double>& regionT, const std::vector<double>& regionP, int tile);

/// The map at the render's size, RGB8 ready for writeDisplayImage: every pixel the colour of the
/// tile regionMeans puts it in (pathlab/images/false_colour.h's diverging palette, ±tileZSaturation
/// at its ends); a tile without a z-score grey. Empty when the statistics do not hold
/// `tilesPerSide`² tiles.
std::vector<unsigned char> tileZImage(const std::vector<double>& regionT,
                                      const std::vector<double>& regionP, int tilesPerSide,
                                      int width, int height);

/// The map's scale for the page: the palette as a bar from −tileZSaturation to +, labelled.
std::string tileZLegendHtml();

} // namespace pathlab::grader
