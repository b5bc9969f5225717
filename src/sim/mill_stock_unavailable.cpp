// Placeholder until the mill height-field model lands: it replaces this file with
// sim/mill_stock.cpp (and the line in src/CMakeLists.txt).
#include "sim/stock_model.hpp"

namespace ncvm {

std::unique_ptr<StockModel> makeMillStock(const Setup&) {
  throw SetupError("mill stock simulation not available", "stock");
}

}  // namespace ncvm
