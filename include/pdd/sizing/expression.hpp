/// \file expression.hpp
/// pdd::expression_sizing: a sizing field from an expression string in x and y, parsed and
/// evaluated by muParser (libmuparser-dev), e.g. "1e-4*(1+10*x^2)".
///
/// Link target: pdd::expression (pdd::pdd plus muParser). muParser is a compiled library,
/// unlike everything else pdd needs, so only programs that parse expressions link it.
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/errors.hpp>

#include <muParser.h>
#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace pdd {

/// Models SizingField by evaluating an expression of x and y with muParser: the operators
/// + - * / ^, comparisons and `?:`, the functions sin cos tan asin acos atan sinh cosh tanh
/// asinh acosh atanh log2 log10 log ln exp sqrt sign rint abs min max sum avg, and the
/// constants _pi and _e. It has no range(): pdd::sizing_range bounds it on a grid (see its
/// safety rule). Each thread evaluates with its own parser (muParser objects are not
/// thread-safe), created on the thread's first call.
/// Thread-safety: area_at may run concurrently; copies share the parsers.
class expression_sizing {
public:
  /// Parses the expression and evaluates it once at (0, 0) to check it.
  /// \throws pdd::sizing_error "sizing expression '<text>': column <c>: <muParser's message>"
  /// with column() = c, the 1-based column of the bad token (the end of the text when the
  /// expression ends too early), for a syntax error, an unknown name or a bad argument count.
  explicit expression_sizing(std::string text) : state_(std::make_shared<state>(std::move(text))) {
    (void)state_->local().eval({0.0, 0.0}, state_->text);
  }

  /// The expression's value at p. \throws pdd::sizing_error when it is NaN or <= 0 there.
  double area_at(const point& p) const {
    const double v = state_->local().eval(p, state_->text);
    if (!(v > 0.0))
      throw sizing_error("sizing expression '" + state_->text + "' is " + std::to_string(v) +
                         " at (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                         "); a maximum area must be > 0");
    return v;
  }

  /// The expression as given to the constructor.
  const std::string& text() const noexcept { return state_->text; }
  /// "expression": the field's name in reports (any_sizing::kind, min_sizing::kind).
  static constexpr const char* kind() noexcept { return "expression"; }

private:
  /// One thread's parser, its variables bound to its own x and y (so it never moves).
  struct evaluator {
    double x = 0.0, y = 0.0;
    mu::Parser parser;

    explicit evaluator(const std::string& text) {
      try {
        parser.DefineVar("x", &x);
        parser.DefineVar("y", &y);
        parser.SetExpr(text);
      } catch (const mu::Parser::exception_type& e) {
        fail(e, text);
      }
    }
    double eval(const point& p, const std::string& text) {
      x = p.x;
      y = p.y;
      try {
        return parser.Eval();
      } catch (const mu::Parser::exception_type& e) {
        fail(e, text);
      }
    }
    [[noreturn]] static void fail(const mu::Parser::exception_type& e, const std::string& text) {
      // muParser's positions are 0-based; past the end (or -1) means the text ended early
      const std::size_t end = text.size() + 1;
      const std::size_t column =
          e.GetPos() >= 0 ? std::min(static_cast<std::size_t>(e.GetPos()) + 1, end) : end;
      throw sizing_error("sizing expression '" + text + "': column " + std::to_string(column) +
                             ": " + e.GetMsg(),
                         column);
    }
  };

  struct state {
    explicit state(std::string t) : text(std::move(t)) {}
    evaluator& local() {
      std::unique_ptr<evaluator>& e = parsers.local();
      if (!e) e = std::make_unique<evaluator>(text);
      return *e;
    }
    std::string text;
    tbb::enumerable_thread_specific<std::unique_ptr<evaluator>> parsers;
  };

  std::shared_ptr<state> state_;
};
static_assert(SizingField<expression_sizing>);

} // namespace pdd
