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
typedef double16 real16;
#define REAL_EPS DBL_EPSILON
#define R(x)     x
#else
typedef float real;
typedef float2 real2;
typedef float4 real4;
typedef float8 real8;
typedef float16 real16;
#define REAL_EPS FLT_EPSILON
#define R(x)     x##f
#endif

/* The neighbour loops' lanes (NEIGH_FOR_LANES, grid.cl): a vector of NEIGH_W reals, 256 bits in
 * double and float, or 8 doubles (512 bits) with NEIGH_LANES = 8 (the host's choice: AVX-512,
 * host/runtime/prog.c). maskw is what comparing two realw gives (lanes all ones or all zeros). */
#ifndef NEIGH_LANES
#define NEIGH_LANES 4
#endif
#if CLSPH_DOUBLE && NEIGH_LANES == 8
#define NEIGH_W 8
typedef double8 realw;
typedef long8 maskw;
typedef uint8 uintw;
typedef int8 intw;
#define LANES_IOTA     ((uint8)(0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u))
#define LANES_MASK(c)  convert_long8(c) /* an int8 comparison as a mask of realw */
#define LANES_INT(m)   convert_int8(m)
#define LANES_VLOAD    vload8
#define LANES_VSTORE_I vstore8
#define LANES_VSTORE_R vstore8
#elif CLSPH_DOUBLE
#define NEIGH_W        4
typedef double4 realw;
typedef long4 maskw;
typedef uint4 uintw;
typedef int4 intw;
#define LANES_IOTA     ((uint4)(0u, 1u, 2u, 3u))
#define LANES_MASK(c)  convert_long4(c) /* an int4 comparison as a mask of realw */
#define LANES_INT(m)   convert_int4(m)
#define LANES_VLOAD    vload4
#define LANES_VSTORE_I vstore4
#define LANES_VSTORE_R vstore4
#else
#define NEIGH_W        8
typedef float8 realw;
typedef int8 maskw;
typedef uint8 uintw;
typedef int8 intw;
#define LANES_IOTA     ((uint8)(0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u))
#define LANES_MASK(c)  (c)
#define LANES_INT(m)   (m)
#define LANES_VLOAD    vload8
#define LANES_VSTORE_I vstore8
#define LANES_VSTORE_R vstore8
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
