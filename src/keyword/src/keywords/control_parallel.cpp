// *CONTROL_PARALLEL: LS-DYNA's shared-memory settings. NCPU becomes `plyform run`'s thread
// count when --threads is not given (the command line wins, as LS-DYNA's ncpu= does). plyform
// always sums the forces in a fixed order (docs/architecture.md, Threads), so its results do
// not depend on the thread count: what LS-DYNA's consistency mode (a negative NCPU, CONST 1)
// asks for is always met. A field written with a value that asks for something else plyform
// does not do is warned about by name; the results are the same with any value.
#include <array>
#include <cstdlib>

#include "../keyword_registry.hpp"
#include "common_cards.hpp"

namespace plyform::keyword {
namespace {

constexpr std::array kZeroOne{0, 1};
constexpr std::array kConst{0, 1, 2};
constexpr std::array kPara{0, 1, 2};

constexpr std::array kFields{
    FieldSpec{.name = "NCPU",
              .type = FieldType::kInteger,
              .default_value = 1,
              .min_value = -1024,
              .max_value = 1024,
              .unit = "-",
              .description = "CPUs: `plyform run` takes as many threads as NCPU says (its "
                             "magnitude) when --threads is not "
                             "given (0 reads as 1). A negative NCPU asks LS-DYNA for results "
                             "independent of the thread count (consistency): plyform's always "
                             "are, so it needs no warning"},
    FieldSpec{.name = "NUMRHS",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "right-hand sides: 0 one per CPU, 1 one. plyform adds every "
                             "thread's forces into one array in colour order; 0 with more than "
                             "one thread is warned about",
              .allowed = kZeroOne,
              .allowed_note = "NUMRHS takes 0 or 1"},
    FieldSpec{.name = "CONST",
              .type = FieldType::kInteger,
              .default_value = 2,
              .unit = "-",
              .description = "consistency: 1 on (met: plyform's results never depend on the "
                             "thread count), 2 off for speed (0 reads as 2); a written 2 is "
                             "warned about, plyform stays consistent",
              .allowed = kConst,
              .allowed_note = "CONST takes 1 (on) or 2 (off)"},
    FieldSpec{.name = "PARA",
              .type = FieldType::kInteger,
              .unit = "-",
              .description = "parallel force assembly with CONST 1: 0 off, 1 and 2 on (met: "
                             "plyform assembles in parallel, in a fixed order); a written 0 "
                             "with CONST 1 is warned about",
              .allowed = kPara,
              .allowed_note = "PARA takes 0, 1 or 2"},
};
constexpr std::array kCards{
    CardSpec{.title = "Card 1", .fields = kFields, .presence = "required"},
};

void read_control_parallel(KeywordInput& in) {
  const auto line = in.next_line();
  if (!line)
    in.fail(in.keyword().line, "", "missing card 1 (NCPU NUMRHS CONST PARA)");
  const CardValues v = in.read(kCards[0], *line);
  model::ControlParallelDesc d{.ncpu = v.integer("NCPU"),
                               .numrhs = v.integer("NUMRHS"),
                               .consistency = zero_means(v.integer("CONST"), 2) == 1 ? 1 : 2,
                               .para = v.integer("PARA"),
                               .where = in.where(line->line)};
  if (!v.blank("NUMRHS") && d.numrhs == 0 && d.threads() > 1) {
    in.warn(line->line, "NUMRHS",
            fmt::format("NUMRHS 0 (a right-hand side per CPU) is not done: plyform's {} threads "
                        "add their forces into one array, in a fixed order (same results)",
                        d.threads()));
  }
  if (!v.blank("CONST") && v.integer("CONST") == 2) {
    in.warn(line->line, "CONST",
            "CONST 2 (consistency off, for speed) is not done: plyform sums the forces in a "
            "fixed order, so its results are the same with any thread count");
  }
  if (!v.blank("PARA") && d.para == 0 && d.consistency == 1) {
    in.warn(line->line, "PARA",
            "PARA 0 (serial force assembly under CONST 1) is not done: plyform assembles the "
            "forces in parallel, in a fixed order (same results)");
  }
  if (has_more_cards(in)) {
    const auto extra = in.next_nonblank_line();
    in.fail(extra->line, "", "*CONTROL_PARALLEL has one card");
  }
  store_once(in, in.model().parallel, d);
}

}  // namespace

KeywordSpec control_parallel_keyword() {
  return {
      .name = "CONTROL_PARALLEL",
      .options = kNoOptions,
      .handler = read_control_parallel,
      .cards = kCards,
      .summary =
          "Shared-memory parallel settings. NCPU (its magnitude) is `plyform run`'s thread count "
          "when --threads is not given (the command line wins). plyform's results "
          "never depend on the thread count, so the consistency LS-DYNA gives with a "
          "negative NCPU or CONST 1 is always there; a field written with a value "
          "that asks for something plyform does not do (NUMRHS 0 with several "
          "threads, CONST 2, PARA 0 with CONST 1) is warned about by name."};
}

}  // namespace plyform::keyword
