#include "sim/stock_model.hpp"

namespace ncvm {

std::unique_ptr<StockModel> makeStockModel(const Setup& setup) {
  if (!setup.stock.present)
    throw SetupError("stock simulation needs a [stock] section in the setup", "stock");
  return setup.kind == MachineKind::Lathe ? makeLatheStock(setup) : makeMillStock(setup);
}

}  // namespace ncvm
