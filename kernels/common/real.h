/* real.h: precision and dimension switches, first source of every program.
 * Built with -D CLSPH_DOUBLE=0|1 (always) and -D DIM=1|2|3.
 *   real   scalar          realv  position/velocity vector: real (1-D), real2 (2-D), real4 (3-D, .w
 * = 0) realm  symmetric DIM x DIM matrix: 2-D real4 (xx, xy, yy, 0), 3-D real8 (xx, xy, xz, yy, yz,
 * zz, 0, 0) Literals are written R(0.5) so that a float build never promotes to double. */
#if CLSPH_DOUBLE
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double real;
typedef double2 real2;
typedef double4 real4;
typedef double8 real8;
#define REAL_EPS DBL_EPSILON
#define R(x)     x
#else
typedef float real;
typedef float2 real2;
typedef float4 real4;
typedef float8 real8;
#define REAL_EPS FLT_EPSILON
#define R(x)     x##f
#endif

#ifndef DIM
#error "DIM (1, 2 or 3) must be defined"
#endif
#if DIM == 1
typedef real realv;
typedef real realm;
#elif DIM == 2
typedef real2 realv;
typedef real4 realm;
#elif DIM == 3
typedef real4 realv;
typedef real8 realm;
#else
#error "DIM must be 1, 2 or 3"
#endif
