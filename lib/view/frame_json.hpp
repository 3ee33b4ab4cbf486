#pragma once
// A Frame as the JSON text the live page draws (page/view.js), and the map
// as a message sent once per page. Coordinates are metres rounded to the
// millimetre, colours "#rrggbb"; point lists are flat [x0, y0, x1, y1, ...]
// arrays, a third the size of a list of pairs.
//
//   {"type":"frame","centre":[x,y],"areas":[{"fill":"#c8e1ff","points":[...]}],
//    "lines":[{"colour":..,"points":[...]}],"dots":[{"colour":..,"radius":1,"points":[...]}],
//    "ellipses":[{"centre":[x,y],"a":..,"b":..,"angle":..,"colour":..}],
//    "bodies":[{"pose":[x,y,yaw],"length":..,"width":..,"colour":..,"filled":true}],
//    "labels":[{"at":[x,y],"text":"7","colour":..}],
//    "legend":[{"text":"laser:0 5.0 Hz","colour":"#000000"}]}
//   {"type":"map","width":W,"height":H,"resolution":r,"origin":[x,y],"cells":"<base64>"}
//     cells: one byte a cell, rows from the lowest y: 0 free, 1 unknown, 2 occupied

#include <string>

#include "algorithms/grid/occupancy_grid.hpp"
#include "view/shapes.hpp"

namespace playerkit::view {

std::string frame_json(const Frame& frame);
std::string map_json(const grid::OccupancyGrid& map);

// "#rrggbb"
std::string colour_text(Colour colour);

}  // namespace playerkit::view
