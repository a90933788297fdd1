// SPDX-License-Identifier: MIT
// satviz: vectors, rotations and rigid transforms in 2D.
#pragma once

#include <cmath>

namespace satviz
{

/// A 2D vector or point. `S` is the scalar type: `double` (the default everywhere) or `float`.
template <typename S>
struct Vec2T
{
    S x{}; ///< x coordinate (to the right)
    S y{}; ///< y coordinate (up)
};

/// Double-precision vector, the default.
using Vec2 = Vec2T<double>;
/// Single-precision vector, for the float instantiation of the algorithms.
using Vec2f = Vec2T<float>;

/// Component-wise sum.
template <typename S>
constexpr Vec2T<S> operator+(Vec2T<S> a, Vec2T<S> b)
{
    return {a.x + b.x, a.y + b.y};
}

/// Component-wise difference.
template <typename S>
constexpr Vec2T<S> operator-(Vec2T<S> a, Vec2T<S> b)
{
    return {a.x - b.x, a.y - b.y};
}

/// Negation.
template <typename S>
constexpr Vec2T<S> operator-(Vec2T<S> a)
{
    return {-a.x, -a.y};
}

/// Scaling by a scalar.
template <typename S>
constexpr Vec2T<S> operator*(S s, Vec2T<S> a)
{
    return {s * a.x, s * a.y};
}

/// Exact component-wise equality.
template <typename S>
constexpr bool operator==(Vec2T<S> a, Vec2T<S> b)
{
    return a.x == b.x && a.y == b.y;
}

/// Exact component-wise inequality.
template <typename S>
constexpr bool operator!=(Vec2T<S> a, Vec2T<S> b)
{
    return !(a == b);
}

/// Dot product.
template <typename S>
constexpr S Dot(Vec2T<S> a, Vec2T<S> b)
{
    return a.x * b.x + a.y * b.y;
}

/// 2D cross product (the z component of the 3D cross product): positive when b is counter-clockwise of a.
template <typename S>
constexpr S Cross(Vec2T<S> a, Vec2T<S> b)
{
    return a.x * b.y - a.y * b.x;
}

/// The vector rotated by +90 degrees (counter-clockwise): (-y, x).
template <typename S>
constexpr Vec2T<S> LeftPerp(Vec2T<S> v)
{
    return {-v.y, v.x};
}

/// The vector rotated by -90 degrees (clockwise): (y, -x). For a counter-clockwise polygon this turns an edge
/// vector into its outward normal.
template <typename S>
constexpr Vec2T<S> RightPerp(Vec2T<S> v)
{
    return {v.y, -v.x};
}

/// Squared Euclidean length.
template <typename S>
constexpr S LengthSquared(Vec2T<S> v)
{
    return Dot(v, v);
}

/// Euclidean length, without overflow or underflow in the intermediate squares.
template <typename S>
S Length(Vec2T<S> v)
{
    return std::hypot(v.x, v.y);
}

/// Unit vector in the direction of v; v itself when its length is zero.
template <typename S>
Vec2T<S> Normalize(Vec2T<S> v)
{
    const S length = Length(v);
    if (length == S(0))
    {
        return v;
    }
    return {v.x / length, v.y / length};
}

/// True when both coordinates are finite (neither NaN nor infinite).
template <typename S>
bool IsFinite(Vec2T<S> v)
{
    return std::isfinite(v.x) && std::isfinite(v.y);
}

/// Converts a vector to another scalar type.
template <typename T, typename S>
constexpr Vec2T<T> ConvertVec(Vec2T<S> v)
{
    return {static_cast<T>(v.x), static_cast<T>(v.y)};
}

/// A rotation, stored as the cosine and sine of its angle (counter-clockwise, radians).
template <typename S>
struct RotT
{
    S c{1}; ///< cosine of the angle
    S s{0}; ///< sine of the angle
};

/// Double-precision rotation.
using Rot = RotT<double>;

/// The rotation by `angle` radians counter-clockwise.
template <typename S>
RotT<S> MakeRot(S angle)
{
    return {std::cos(angle), std::sin(angle)};
}

/// Rotates v by q.
template <typename S>
constexpr Vec2T<S> Rotate(RotT<S> q, Vec2T<S> v)
{
    return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y};
}

/// Rotates v by the inverse of q.
template <typename S>
constexpr Vec2T<S> InvRotate(RotT<S> q, Vec2T<S> v)
{
    return {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y};
}

/// The rotation q^T r: r expressed relative to q.
template <typename S>
constexpr RotT<S> InvMulRot(RotT<S> q, RotT<S> r)
{
    return {q.c * r.c + q.s * r.s, q.c * r.s - q.s * r.c};
}

/// A rigid transform: a point p in the local frame maps to Rotate(q, p) + p.
template <typename S>
struct TransformT
{
    Vec2T<S> p{}; ///< translation: the position of the local origin in the parent frame
    RotT<S> q{};  ///< rotation of the local frame
};

/// Double-precision transform.
using Transform = TransformT<double>;

/// The transform with position `position` and rotation by `angle` radians.
template <typename S>
TransformT<S> MakeTransform(Vec2T<S> position, S angle)
{
    return {position, MakeRot(angle)};
}

/// Maps a local point to the parent frame.
template <typename S>
constexpr Vec2T<S> TransformPoint(const TransformT<S>& xf, Vec2T<S> v)
{
    return Rotate(xf.q, v) + xf.p;
}

/// Maps a parent-frame point to the local frame.
template <typename S>
constexpr Vec2T<S> InvTransformPoint(const TransformT<S>& xf, Vec2T<S> v)
{
    return InvRotate(xf.q, v - xf.p);
}

/// The transform of frame B relative to frame A (A^-1 * B). The translation is formed as B.p - A.p before any
/// rotation, so two frames close to each other but far from the origin keep full relative precision.
template <typename S>
constexpr TransformT<S> InvMulTransforms(const TransformT<S>& a, const TransformT<S>& b)
{
    return {InvRotate(a.q, b.p - a.p), InvMulRot(a.q, b.q)};
}

} // namespace satviz
