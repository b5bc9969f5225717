// Expression bytecode evaluation and the Macro B functions (fanuc-reference B.2-B.4).
#include <cmath>
#include <numbers>

#include "exec/executor.hpp"
#include "lang/address_letters.hpp"

namespace ncvm {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Stack slots: five bracket levels bound the depth of any legal expression well below this.
constexpr int kStack = 64;

double checked(double v) {
  if (!std::isfinite(v)) throw AlarmError(AlarmId::FloatOverflow);
  return v;
}

int64_t toInteger(double v) {
  if (!std::isfinite(v) || std::fabs(v) > 9.0e15) throw AlarmError(AlarmId::IntegerOverflow);
  return std::llround(v);
}

// SIN and COS are exact at multiples of 90 degrees, as on the control (COS[90] is 0, so
// TAN[90] divides by zero).
double sinDeg(double d) {
  // Only a whole number of degrees can be a multiple of 90 (fmod below is exact, so a value
  // with a fraction keeps it): such an angle needs no reduction at all, and a whole one below
  // 9e15 is reduced in integers, exactly as fmod would. fmod (about 200 instructions beyond one
  // turn) only for the rest.
  if (std::fabs(d) < 9.0e15) {
    const auto whole = static_cast<int64_t>(d);
    if (static_cast<double>(whole) != d) return std::sin(d * kDeg);
    int64_t m = whole % 360;
    if (m < 0) m += 360;
    if (m == 0 || m == 180) return 0.0;
    if (m == 90) return 1.0;
    if (m == 270) return -1.0;
    return std::sin(d * kDeg);
  }
  double r = (d > -360.0 && d < 360.0) ? d : std::fmod(d, 360.0);
  if (r < 0) r += 360.0;
  if (r == 0 || r == 180) return 0.0;
  if (r == 90) return 1.0;
  if (r == 270) return -1.0;
  return std::sin(d * kDeg);
}
double cosDeg(double d) {
  return sinDeg(d + 90.0);
}

double bcdToBinary(double x) {
  int64_t v = toInteger(x);
  if (v < 0) throw AlarmError(AlarmId::ArgumentOutOfRange, "BIN of a negative value");
  int64_t out = 0, mul = 1;
  while (v) {
    int64_t digit = v & 0xF;
    if (digit > 9) throw AlarmError(AlarmId::ArgumentOutOfRange, "BIN of a value that is not BCD");
    out += digit * mul;
    mul *= 10;
    v >>= 4;
  }
  return static_cast<double>(out);
}

double binaryToBcd(double x) {
  int64_t v = toInteger(x);
  if (v < 0 || v > 99999999)
    throw AlarmError(AlarmId::ArgumentOutOfRange, "BCD of a value out of 0-99999999");
  int64_t out = 0;
  int shift = 0;
  while (v) {
    out |= (v % 10) << shift;
    v /= 10;
    shift += 4;
  }
  return static_cast<double>(out);
}

}  // namespace

double Executor::callFn(Fn fn, double a, double b, int32_t arg) {
  bool nat = nat_;
  switch (fn) {
    case Fn::Sin:
      return sinDeg(a);
    case Fn::Cos:
      return cosDeg(a);
    case Fn::Tan: {
      double c = cosDeg(a);
      if (c == 0.0) throw AlarmError(AlarmId::ZeroDivide, "TAN of 90 degrees");
      return checked(sinDeg(a) / c);
    }
    case Fn::Asin: {
      if (a < -1.0 || a > 1.0) throw AlarmError(AlarmId::ArgumentOutOfRange, "ASIN beyond 1");
      double r = std::asin(a) / kDeg;
      return (!nat && r < 0) ? r + 360.0 : r;  // NAT=0: 270..90
    }
    case Fn::Acos:
      if (a < -1.0 || a > 1.0) throw AlarmError(AlarmId::ArgumentOutOfRange, "ACOS beyond 1");
      return std::acos(a) / kDeg;
    case Fn::Atan: {
      double r = std::atan(a) / kDeg;
      return (!nat && r < 0) ? r + 360.0 : r;
    }
    case Fn::Atan2: {
      if (a == 0 && b == 0) throw AlarmError(AlarmId::ArgumentOutOfRange, "ATAN[0]/[0]");
      double r = std::atan2(a, b) / kDeg;
      return (!nat && r < 0) ? r + 360.0 : r;  // NAT=0: 0..360
    }
    case Fn::Sqrt:
      if (a < 0) throw AlarmError(AlarmId::ArgumentOutOfRange, "SQRT of a negative value");
      return std::sqrt(a);
    case Fn::Abs:
      return std::fabs(a);
    case Fn::Bin:
      return bcdToBinary(a);
    case Fn::Bcd:
      return binaryToBcd(a);
    case Fn::Round:  // halves away from zero; in an NC address to its least increment
      return roundPerUnit_ > 1 ? std::round(a * roundPerUnit_) / roundPerUnit_ : std::round(a);
    case Fn::Fix:
      return std::trunc(a);
    case Fn::Fup:
      return a >= 0 ? std::ceil(a) : std::floor(a);
    case Fn::Ln:
      if (a <= 0) throw AlarmError(AlarmId::ArgumentOutOfRange, "LN of zero or a negative value");
      return std::log(a);
    case Fn::Exp:
      return checked(std::exp(a));
    case Fn::Pow: {
      if (a == 0 && b < 0) throw AlarmError(AlarmId::ZeroDivide, "POW of zero to a negative power");
      if (a < 0 && b != std::trunc(b))
        throw AlarmError(AlarmId::ArgumentOutOfRange,
                         "POW of a negative value to a fractional power");
      return checked(std::pow(a, b));
    }
    case Fn::Adp: {
      // ADP[#n]: undo the least-increment scaling of an argument written without a point.
      const double scale = vars_.noPointScale(frames_.back().level, arg);
      return scale > 0 ? a * scale : a;
    }
  }
  return a;
}

// The 16i class holds macro values to about 8 significant decimal digits (macroDigits_):
// every constant, variable read and result is rounded to them, so 1 + 0.0000000001 is 1 and
// the manual's 9876543210123.456 is 9876543200000. With 0 the values are doubles.
Value Executor::roundedToMacroDigits(Value v) const {
  if (v.null || v.v == 0 || !std::isfinite(v.v)) return v;
  const int shift = macroDigits_ - 1 - static_cast<int>(std::floor(std::log10(std::fabs(v.v))));
  // Powers of ten up to 1e22 are exact doubles; dividing by one keeps large values exact.
  if (shift > 300 || shift < -300) return v;
  const double scale = std::pow(10.0, std::abs(shift));
  v.v = shift >= 0 ? std::round(v.v * scale) / scale : std::round(v.v / scale) * scale;
  return v;
}

Value Executor::eval(int32_t expr) {
  const Program& p = *frames_.back().prog;
  const ExprRange r = p.exprs[static_cast<size_t>(expr)];
  const Instr* code = p.code.data();
  // Hot path: a plain variable or constant needs no stack.
  if (r.end - r.begin == 1) {
    const Instr& in = code[r.begin];
    if (in.op == Op::Const)
      return macroPrecision(Value::num(p.consts[static_cast<size_t>(in.arg)]));
    if (in.op == Op::Var) return macroPrecision(readVar(in.arg));
  }
  Value* st = evalStack_.data();  // eval never re-enters itself: one stack serves
  int sp = 0;
  for (uint32_t k = r.begin; k < r.end; ++k) {
    const Instr& in = code[k];
    try {
      switch (in.op) {
        case Op::Const:
          if (sp >= kStack)
            throw AlarmError(AlarmId::IllegalExpressionFormat, "expression too deep");
          st[sp++] = macroPrecision(Value::num(p.consts[static_cast<size_t>(in.arg)]));
          break;
        case Op::Var:
          if (sp >= kStack)
            throw AlarmError(AlarmId::IllegalExpressionFormat, "expression too deep");
          st[sp++] = macroPrecision(readVar(in.arg));
          break;
        case Op::VarInd: {
          double n = st[sp - 1].asNumber();
          if (!std::isfinite(n) || std::fabs(n) > 1e9)
            throw AlarmError(AlarmId::VariableOutOfRange);
          st[sp - 1] = macroPrecision(readVar(std::llround(n)));
          break;
        }
        case Op::Neg:
          st[sp - 1] = Value::num(-st[sp - 1].asNumber());
          break;
        case Op::Fn1:
          st[sp - 1] =
              macroPrecision(Value::num(checked(callFn(in.fn, st[sp - 1].asNumber(), 0, in.arg))));
          break;
        case Op::Fn2:
          --sp;
          st[sp - 1] = macroPrecision(
              Value::num(checked(callFn(in.fn, st[sp - 1].asNumber(), st[sp].asNumber(), in.arg))));
          break;
        case Op::Eq:
        case Op::Ne: {
          // Only EQ and NE tell vacant from zero.
          --sp;
          const Value a = st[sp - 1], b = st[sp];
          bool eq = (a.null || b.null) ? (a.null && b.null) : a.v == b.v;
          st[sp - 1] = Value::num((in.op == Op::Eq) == eq ? 1.0 : 0.0);
          break;
        }
        default: {
          --sp;
          double a = st[sp - 1].asNumber(), b = st[sp].asNumber();
          double v = 0;
          switch (in.op) {
            case Op::Add:
              v = a + b;
              break;
            case Op::Sub:
              v = a - b;
              break;
            case Op::Mul:
              v = a * b;
              break;
            case Op::Div:
              if (b == 0) throw AlarmError(AlarmId::ZeroDivide);
              v = a / b;
              break;
            case Op::Mod:
              if (b == 0) throw AlarmError(AlarmId::ZeroDivide, "MOD by zero");
              v = std::fmod(a, b);
              break;
            case Op::And:
              v = static_cast<double>(toInteger(a) & toInteger(b));
              break;
            case Op::Or:
              v = static_cast<double>(toInteger(a) | toInteger(b));
              break;
            case Op::Xor:
              v = static_cast<double>(toInteger(a) ^ toInteger(b));
              break;
            case Op::LAnd:
              v = (a != 0 && b != 0) ? 1 : 0;
              break;
            case Op::LOr:
              v = (a != 0 || b != 0) ? 1 : 0;
              break;
            case Op::LXor:
              v = ((a != 0) != (b != 0)) ? 1 : 0;
              break;
            case Op::Gt:
              v = a > b;
              break;
            case Op::Ge:
              v = a >= b;
              break;
            case Op::Lt:
              v = a < b;
              break;
            case Op::Le:
              v = a <= b;
              break;
            default:
              break;
          }
          st[sp - 1] = macroPrecision(Value::num(checked(v)));
        }
      }
    } catch (AlarmError& e) {
      if (!e.col && !e.hasLoc) e.col = in.col;
      throw;
    }
  }
  return st[sp - 1];
}

Value Executor::evalAddress(int32_t expr, char letter) {
  // ROUND in an address rounds to the address's least input increment (1.00333 -> 1.003 mm):
  // incremental moves of rounded values then add up to what the axis really moved. A
  // rotary axis counts degrees, whose increment does not follow G20/G21.
  bool length = letters::isDimension(letter) || letter == 'c' || letter == 'r';
  bool degrees = letter == 'A' || letter == 'B' || letter == 'C';
  roundPerUnit_ = length ? static_cast<double>(incrementsPerUnit(
                               setup_.increment, degrees ? InputUnit::Mm : modal_.unit))
                         : 1.0;
  struct Restore {
    double& v;
    ~Restore() { v = 1.0; }
  } restore{roundPerUnit_};
  return eval(expr);
}

bool Executor::evalCond(int32_t expr) {
  return eval(expr).asNumber() != 0.0;
}

}  // namespace ncvm
