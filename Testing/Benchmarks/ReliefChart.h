// Charts of the bench, drawn by VTK's vtkChartXY offscreen and written as PNG.
#ifndef ReliefChart_h
#define ReliefChart_h

#include <string>
#include <vector>

namespace ReliefChart
{
/// Errors below this are drawn at it: a log axis has no zero.
constexpr double LogFloor = 1e-6;

/// Points or a polyline, in the colour of its place in the list (a black line when
/// Black is set).
struct Series
{
  std::string Name;
  std::vector<double> X;
  std::vector<double> Y;
  bool Line = false;
  bool Black = false;
};

struct Axes
{
  std::string Title;
  std::string X;
  std::string Y;
  bool LogX = false;
  bool LogY = false;
  double YRange[2] = { 0.0, 0.0 }; ///< fixed when the first is below the second, else fitted
};

/// Draws `series` on 900x600 pixels and writes the PNG `file` (its folder must exist).
void Write(const std::vector<Series>& series, const Axes& axes, const std::string& file);
}

#endif
