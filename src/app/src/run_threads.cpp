// The thread count of `plyform run`: the command line's --threads wins over the deck's
// *CONTROL_PARALLEL NCPU, as LS-DYNA's ncpu= does over its card.

#include "plyform/app/commands.hpp"
#include "plyform/model/model_desc.hpp"

namespace plyform::app {

RunOptions with_deck_threads(RunOptions options, const model::ModelDesc& deck) {
  if (options.threads <= 0)
    options.threads = deck.parallel ? deck.parallel->threads() : 1;
  return options;
}

}  // namespace plyform::app
