#pragma once
// The imaginary tip directions of a lathe insert (fanuc-reference E.2): where the imaginary
// tip lies relative to the nose-radius centre, as the signs of (X radius, Z), X+ up, Z+ right:
//   2 6 1
//   7 0 5      0 and 9: the program describes the nose centre (no tip vector)
//   3 8 4
// Shared by tool-nose radius compensation (the tip vector R * signs) and the lathe stock
// model (the insert's orientation), so the two can never disagree.
namespace ncvm::lathe {

struct TipSigns {
  int x = 0, z = 0;
};

constexpr TipSigns tipSigns(int tip) {
  switch (tip) {
    case 1:
      return {1, 1};
    case 2:
      return {1, -1};
    case 3:
      return {-1, -1};
    case 4:
      return {-1, 1};
    case 5:
      return {0, 1};
    case 6:
      return {1, 0};
    case 7:
      return {0, -1};
    case 8:
      return {-1, 0};
    default:
      return {0, 0};
  }
}

}  // namespace ncvm::lathe
