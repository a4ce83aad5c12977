// Draws fig/templates.svg: the three 2-refinement templates exactly as the library stores them
// (internal/template_table.h), each corner labelled with its angle computed from the table.
//
//   g++ -std=c++17 -I include doc/Quad_mesher_2/fig/make_templates_svg.cpp -o /tmp/make_templates_svg
//   /tmp/make_templates_svg > doc/Quad_mesher_2/fig/templates.svg
//
// (run from the repository root; needs no CGAL, template_table.h is self-contained)

#include <CGAL/Quad_mesher_2/internal/template_table.h>

#include <cmath>
#include <cstdio>

namespace QI = CGAL::Quad_mesher_2::internal;

namespace {

const double unit = 80;   // pixels per half cell side
const double panel = 260; // horizontal distance between panels
const double top = 40;

double px(int panel_index, double x) { return 60 + panel_index * panel + unit * x; }
double py(double y) { return top + unit * (2 - y); } // y axis up

void draw(int p, const QI::Quad_template& t, const char* title, int active_a, int active_b)
{
  static const int cx[4] = { 0, 2, 2, 0 }, cy[4] = { 0, 0, 2, 2 };
  std::printf("<g>\n<text x=\"%g\" y=\"%g\" text-anchor=\"middle\" font-size=\"15\">%s</text>\n",
              px(p, 1), top + unit * 2 + 34, title);
  for(std::size_t q = 0; q < t.size; ++q) {
    std::printf("<polygon fill=\"#e8f0fb\" stroke=\"#222\" stroke-width=\"2\" points=\"");
    for(int c = 0; c < 4; ++c)
      std::printf("%s%g,%g", c ? " " : "", px(p, t.quads[q][c].x), py(t.quads[q][c].y));
    std::printf("\"/>\n");
    for(int c = 0; c < 4; ++c) {
      const QI::Local_vertex& a = t.quads[q][(c + 3) % 4];
      const QI::Local_vertex& v = t.quads[q][c];
      const QI::Local_vertex& b = t.quads[q][(c + 1) % 4];
      const double ux = a.x - v.x, uy = a.y - v.y, wx = b.x - v.x, wy = b.y - v.y;
      const double lu = std::hypot(ux, uy), lw = std::hypot(wx, wy);
      const double angle =
        std::acos((ux * wx + uy * wy) / (lu * lw)) * 180.0 / 3.14159265358979323846;
      double dx = ux / lu + wx / lw, dy = uy / lu + wy / lw; // interior bisector
      const double ld = std::hypot(dx, dy);
      dx /= ld;
      dy /= ld;
      const double d = angle < 60 ? 0.42 : 0.24; // sharp corners: label further in
      std::printf("<text x=\"%g\" y=\"%g\" text-anchor=\"middle\" dominant-baseline=\"central\" "
                  "font-size=\"11\" fill=\"#a0301c\">%.0f&#176;</text>\n",
                  px(p, v.x + d * dx), py(v.y + d * dy), angle);
    }
  }
  for(int c : { active_a, active_b })
    if(c >= 0)
      std::printf("<circle cx=\"%g\" cy=\"%g\" r=\"6\" fill=\"#1f5fd6\"/>\n", px(p, cx[c]),
                  py(cy[c]));
  std::printf("</g>\n");
}

} // namespace

int main()
{
  const double width = 120 + 2 * panel + 2 * unit, height = top + 2 * unit + 80;
  std::printf("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
              "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%g\" "
              "height=\"%g\" viewBox=\"0 0 %g %g\" font-family=\"sans-serif\">\n",
              width, height, width, height);
  std::printf("<title>The 2-refinement templates of Quad_mesher_2</title>\n");
  draw(0, QI::plain_template(), "(a) no active corner: 1 quad", -1, -1);
  draw(1, QI::transition_template(0), "(b) one active corner: transition", 0, -1);
  draw(2, QI::refinement_template(), "(c) two active corners: refinement", 0, 2);
  std::printf("<text x=\"30\" y=\"%g\" font-size=\"12\">blue dot: active corner "
              "(even lattice vertex touching a split cell of the same level)</text>\n",
              height - 12);
  std::printf("</svg>\n");
  return 0;
}
