// Fixed-width signed integers for the integer kernel's exact determinants.
//
// WideInt<N>: N 64-bit limbs, little-endian, two's complement. Addition,
// subtraction and negation are exact modulo 2^(64N); `mul<R>` multiplies by
// sign and magnitude into R limbs (schoolbook, 64x64->128-bit limb products).
// Every operation gives the exact integer when the exact result satisfies
// |v| < 2^(64N-1) (resp. 2^(64R-1)); the integer kernel proves this bound for
// each intermediate before choosing its type (predicates/integer_kernel.hpp).
//
// IntFor<Bits>: the narrowest of int64, __int128, WideInt<N> that holds every
// integer with |v| < 2^Bits. `value_bits<T>` is that capacity, used in the
// kernel's static_asserts. Written from the definitions (Knuth TAOCP vol. 2,
// 4.3.1, algorithms A, S, M); nothing here is tuned for speed beyond skipping
// zero limbs.
#pragma once
#include <array>
#include <cstdint>
#include <type_traits>

namespace dlab {

__extension__ typedef __int128 int128;            // g++: available in ISO mode too
__extension__ typedef unsigned __int128 uint128;

template <int N>
struct WideInt {
  static_assert(N >= 1);
  std::array<std::uint64_t, N> limb{};  // limb[0] least significant

  constexpr WideInt() = default;
  constexpr explicit WideInt(std::int64_t v) {
    limb[0] = static_cast<std::uint64_t>(v);
    for (int i = 1; i < N; ++i) limb[i] = v < 0 ? ~std::uint64_t{0} : 0;
  }
  constexpr explicit WideInt(int128 v)
    requires(N >= 2)
  {
    limb[0] = static_cast<std::uint64_t>(v);
    limb[1] = static_cast<std::uint64_t>(static_cast<uint128>(v) >> 64);
    for (int i = 2; i < N; ++i) limb[i] = v < 0 ? ~std::uint64_t{0} : 0;
  }
  template <int M>
    requires(M < N)
  constexpr explicit WideInt(const WideInt<M>& v) {  // sign extension
    for (int i = 0; i < M; ++i) limb[i] = v.limb[i];
    for (int i = M; i < N; ++i) limb[i] = v.negative() ? ~std::uint64_t{0} : 0;
  }

  constexpr bool negative() const { return (limb[N - 1] >> 63) != 0; }
  constexpr int sign() const {
    if (negative()) return -1;
    for (int i = 0; i < N; ++i)
      if (limb[i] != 0) return 1;
    return 0;
  }

  friend constexpr WideInt operator+(const WideInt& a, const WideInt& b) {
    WideInt r;
    std::uint64_t carry = 0;
    _Pragma("GCC unroll 8") for (int i = 0; i < N; ++i) {
      const std::uint64_t s = a.limb[i] + b.limb[i];
      const std::uint64_t t = s + carry;
      carry = static_cast<std::uint64_t>(s < a.limb[i]) | static_cast<std::uint64_t>(t < s);
      r.limb[i] = t;
    }
    return r;
  }
  friend constexpr WideInt operator-(const WideInt& a, const WideInt& b) {
    WideInt r;
    std::uint64_t borrow = 0;
    _Pragma("GCC unroll 8") for (int i = 0; i < N; ++i) {
      const std::uint64_t d = a.limb[i] - b.limb[i];
      const std::uint64_t t = d - borrow;
      borrow = static_cast<std::uint64_t>(a.limb[i] < b.limb[i]) |
               static_cast<std::uint64_t>(d < borrow);
      r.limb[i] = t;
    }
    return r;
  }
  friend constexpr WideInt operator-(const WideInt& a) { return WideInt{} - a; }
  friend constexpr bool operator==(const WideInt&, const WideInt&) = default;
};

// |v| < 2^Bits fits in IntFor<Bits>.
template <int Bits>
using IntFor = std::conditional_t<
    (Bits <= 63), std::int64_t,
    std::conditional_t<(Bits <= 127), int128, WideInt<Bits / 64 + 1>>>;

template <class T>
struct IsWide : std::false_type {};
template <int N>
struct IsWide<WideInt<N>> : std::true_type {};

// Largest b such that every |v| < 2^b is representable in T.
template <class T>
inline constexpr int value_bits = 0;
template <>
inline constexpr int value_bits<std::int64_t> = 63;
template <>
inline constexpr int value_bits<int128> = 127;
template <int N>
inline constexpr int value_bits<WideInt<N>> = 64 * N - 1;

constexpr WideInt<1> as_wide(std::int64_t v) { return WideInt<1>(v); }
constexpr WideInt<2> as_wide(int128 v) { return WideInt<2>(v); }
template <int N>
constexpr const WideInt<N>& as_wide(const WideInt<N>& v) { return v; }

// Exact conversion to a type at least as wide.
template <class T, class S>
constexpr T widen(const S& x) {
  static_assert(value_bits<T> >= value_bits<S>, "widen: narrowing");
  if constexpr (IsWide<T>::value) {
    if constexpr (IsWide<S>::value && std::is_same_v<S, T>)
      return x;
    else
      return T(as_wide(x));
  } else {
    return static_cast<T>(x);
  }
}

// a * b in R limbs, by magnitudes; exact when |a b| < 2^(64R-1).
template <int R, int A, int B>
constexpr WideInt<R> mul(const WideInt<A>& a, const WideInt<B>& b) {
  const WideInt<A> ua = a.negative() ? -a : a;
  const WideInt<B> ub = b.negative() ? -b : b;
  WideInt<R> r;
  _Pragma("GCC unroll 8") for (int i = 0; i < A && i < R; ++i) {
    std::uint64_t carry = 0;
    _Pragma("GCC unroll 8") for (int j = 0; j < B; ++j) {
      if (i + j >= R) break;
      const uint128 t = static_cast<uint128>(ua.limb[i]) * ub.limb[j] + r.limb[i + j] + carry;
      r.limb[i + j] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    if (i + B < R) r.limb[i + B] = carry;  // untouched by earlier rows
  }
  return a.negative() != b.negative() ? -r : r;
}

// a * b computed in T (exact when the product fits T: the caller's budget).
template <class T, class X, class Y>
constexpr T mul_in(const X& a, const Y& b) {
  if constexpr (IsWide<T>::value) {
    constexpr int R = (value_bits<T> + 1) / 64;
    return mul<R>(as_wide(a), as_wide(b));
  } else {
    return static_cast<T>(widen<T>(a) * widen<T>(b));
  }
}

template <class T>
constexpr int sign_int(const T& v) {
  if constexpr (IsWide<T>::value)
    return v.sign();
  else
    return (v > 0) - (v < 0);
}

}  // namespace dlab
