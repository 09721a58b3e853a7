#include "ReliefChart.h"

#include "vtkAxis.h"
#include "vtkChartLegend.h"
#include "vtkChartXY.h"
#include "vtkContextScene.h"
#include "vtkContextView.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPlot.h"
#include "vtkPlotPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTable.h"
#include "vtkWindowToImageFilter.h"

#include <iterator>

namespace
{
// Matplotlib's "tab10" colours, then two more: distinct at a glance and for most
// colour-blind readers.
constexpr unsigned char Palette[][3] = { { 31, 119, 180 }, { 255, 127, 14 }, { 44, 160, 44 },
  { 214, 39, 40 }, { 148, 103, 189 }, { 140, 86, 75 }, { 227, 119, 194 }, { 127, 127, 127 },
  { 188, 189, 34 }, { 23, 190, 207 }, { 0, 0, 128 }, { 128, 128, 0 } };
}

namespace ReliefChart
{
void Write(const std::vector<Series>& series, const Axes& axes, const std::string& file)
{
  vtkNew<vtkContextView> view;
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetSize(900, 600);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetTitle(axes.Title);
  chart->SetShowLegend(true);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(axes.X);
  chart->GetAxis(vtkAxis::BOTTOM)->SetLogScale(axes.LogX);
  chart->GetAxis(vtkAxis::LEFT)->SetTitle(axes.Y);
  chart->GetAxis(vtkAxis::LEFT)->SetLogScale(axes.LogY);
  if (axes.YRange[0] < axes.YRange[1])
  {
    chart->GetAxis(vtkAxis::LEFT)->SetBehavior(vtkAxis::FIXED);
    chart->GetAxis(vtkAxis::LEFT)->SetUnscaledRange(axes.YRange[0], axes.YRange[1]);
  }
  for (size_t s = 0; s < series.size(); ++s)
  {
    vtkNew<vtkTable> table;
    vtkNew<vtkDoubleArray> x;
    x->SetName("x");
    vtkNew<vtkDoubleArray> y;
    y->SetName(series[s].Name.c_str());
    for (size_t i = 0; i < series[s].X.size(); ++i)
    {
      x->InsertNextValue(series[s].X[i]);
      y->InsertNextValue(series[s].Y[i]);
    }
    table->AddColumn(x);
    table->AddColumn(y);
    vtkPlot* plot = chart->AddPlot(series[s].Line ? vtkChart::LINE : vtkChart::POINTS);
    plot->SetInputData(table, 0, 1);
    const unsigned char* colour = Palette[s % std::size(Palette)];
    if (series[s].Black)
    {
      plot->SetColor(0, 0, 0, 255);
    }
    else
    {
      plot->SetColor(colour[0], colour[1], colour[2], 255);
    }
    plot->SetWidth(series[s].Line ? 2.0f : 6.0f);
    if (series[s].Line && !series[s].Black)
    {
      vtkPlotPoints::SafeDownCast(plot)->SetMarkerStyle(vtkPlotPoints::CIRCLE);
    }
  }
  view->GetRenderWindow()->Render();
  vtkNew<vtkWindowToImageFilter> image;
  image->SetInput(view->GetRenderWindow());
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(image->GetOutputPort());
  writer->SetFileName(file.c_str());
  writer->Write();
}
}
