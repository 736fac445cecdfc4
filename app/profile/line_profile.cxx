#include "profile/line_profile.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace shadelab
{
std::vector<Pixel> LinePixels(Pixel from, Pixel to)
{
  const int dx = to.X - from.X, dy = to.Y - from.Y;
  const int steps = std::max(std::abs(dx), std::abs(dy));
  std::vector<Pixel> pixels;
  pixels.reserve(static_cast<std::size_t>(steps) + 1);
  for (int i = 0; i <= steps; ++i)
  {
    const double t = steps ? static_cast<double>(i) / steps : 0;
    pixels.push_back({ from.X + static_cast<int>(std::lround(t * dx)),
      from.Y + static_cast<int>(std::lround(t * dy)) });
  }
  return pixels;
}

double Luminance(const Rgb& c)
{
  return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

std::vector<std::size_t> EdgeCrossings(const LineProfile& profile)
{
  const std::vector<vtkIdType>& t = profile.Triangles;
  std::vector<std::size_t> crossings;
  for (std::size_t i = 0; i + 1 < t.size(); ++i)
  {
    if (t[i] >= 0 && t[i + 1] >= 0 && t[i] != t[i + 1])
    {
      crossings.push_back(i);
    }
  }
  return crossings;
}

ProfileCurve MakeCurve(
  const std::string& label, std::vector<Rgb> values, const std::vector<vtkIdType>& triangles)
{
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  ProfileCurve curve;
  curve.Label = label;
  curve.Values = std::move(values);
  const std::size_t n = curve.Values.size();
  const auto on = [&triangles](std::size_t i) { return triangles[i] >= 0; };
  for (const Rgb& v : curve.Values)
  {
    curve.Luminance.push_back(Luminance(v));
  }
  const std::vector<double>& l = curve.Luminance;
  curve.First.assign(n, none);
  curve.Second.assign(n, none);
  for (std::size_t i = 0; i + 1 < n; ++i)
  {
    if (on(i) && on(i + 1))
    {
      curve.First[i] = l[i + 1] - l[i];
      if (i > 0 && on(i - 1))
      {
        curve.Second[i] = l[i + 1] - 2 * l[i] + l[i - 1];
      }
    }
  }
  return curve;
}

ProfileCurve ReadCurve(
  const std::string& label, const FloatImage& picture, const LineProfile& profile)
{
  std::vector<Rgb> values;
  for (const Pixel& p : profile.Samples)
  {
    values.push_back(PixelRgb(picture, p.X, p.Y));
  }
  return MakeCurve(label, std::move(values), profile.Triangles);
}

std::string ProfileCsv(const LineProfile& profile)
{
  std::vector<const ProfileCurve*> curves;
  for (const ProfileCurve& c : profile.Curves)
  {
    curves.push_back(&c);
  }
  curves.push_back(&profile.Oracle);
  std::ostringstream csv;
  csv.precision(9);
  csv << "sample,x,y,triangle,edge";
  for (const ProfileCurve* c : curves)
  {
    for (const char* column : { "luminance", "r", "g", "b", "first", "second" })
    {
      // A label with a comma or a quote (a mode's KEY=VALUE list) quoted.
      std::string name = c->Label + ' ' + column;
      if (name.find_first_of(",\"") != std::string::npos)
      {
        std::string quoted = "\"";
        for (char ch : name)
        {
          quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        }
        name = quoted + '"';
      }
      csv << ',' << name;
    }
  }
  csv << '\n';
  const auto value = [&csv](double v)
  {
    csv << ',';
    if (!std::isnan(v))
    {
      csv << v;
    }
  };
  for (std::size_t i = 0; i < profile.Samples.size(); ++i)
  {
    csv << i << ',' << profile.Samples[i].X << ',' << profile.Samples[i].Y << ','
        << profile.Triangles[i] << ',' << profile.EdgeDistances[i];
    for (const ProfileCurve* c : curves)
    {
      value(c->Luminance[i]);
      for (double channel : c->Values[i])
      {
        value(channel);
      }
      value(c->First[i]);
      value(c->Second[i]);
    }
    csv << '\n';
  }
  return csv.str();
}
}
