# check_ranks_run.cmake: run `clsph-ranks run` under mpiexec and check its JSON (tests/CMakeLists.txt,
# ranks_run_*). -DMPIEXEC, -DNP, -DEXE, -DOUT, -DCASE, -DARGS (|-separated), -DTOL: the particles'
# positions (in dr) and velocities (over the largest speed) at the end against the whole scene run
# alone, at most TOL apart (0: bit for bit). The split must own every particle once and take the
# whole run's steps (clsph-ranks checks both and fails otherwise), and with more than one rank hold
# a halo (more particles than the scene's) and send particles every step. -DRECUTS=0: the cuts
# must not have moved; 1: they must have (the load following the fluid); unset: either.
# -DCLSPH (the clsph executable): the split also writes its final state (--out OUT.d), which must
# hold every particle once (/particles/id a permutation, read with h5dump) and which
# `clsph render` must draw.
string(REPLACE "|" ";" args "${ARGS}")
file(REMOVE "${OUT}")
if(DEFINED CLSPH)
  file(REMOVE_RECURSE "${OUT}.d")
  list(APPEND args --out "${OUT}.d")
endif()
execute_process(COMMAND "${MPIEXEC}" --oversubscribe -n ${NP} "${EXE}" run "${CASE}" ${args}
                        --json "${OUT}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "clsph-ranks run on ${NP} ranks exited with ${rc}")
endif()
file(READ "${OUT}" j)
foreach(k ranks particles owned steps steps_alone dx_dr dv_rel held_ratio bytes_per_step recuts)
  string(JSON ${k} GET "${j}" ${k})
endforeach()
if(NOT ranks EQUAL NP OR NOT owned EQUAL particles OR NOT steps EQUAL steps_alone)
  message(FATAL_ERROR "ranks ${ranks} (want ${NP}), owned ${owned} of ${particles}, steps ${steps} against ${steps_alone} alone")
endif()
execute_process(COMMAND python3 -c "import sys; x,v,t,h,b,n=map(float,sys.argv[1:]); sys.exit(0 if x <= t and v <= t and (n == 1 or (h > 1 and b > 0)) else 1)"
                        ${dx_dr} ${dv_rel} ${TOL} ${held_ratio} ${bytes_per_step} ${NP}
                RESULT_VARIABLE crc)
if(NOT crc EQUAL 0)
  message(FATAL_ERROR "split against alone: positions ${dx_dr} dr, velocities ${dv_rel} (at most ${TOL}); held ${held_ratio} times the particles, ${bytes_per_step} bytes sent a step")
endif()
if((DEFINED RECUTS AND RECUTS EQUAL 0 AND NOT recuts EQUAL 0) OR
   (DEFINED RECUTS AND RECUTS EQUAL 1 AND recuts EQUAL 0))
  message(FATAL_ERROR "the cuts moved ${recuts} times (RECUTS=${RECUTS})")
endif()
if(DEFINED CLSPH)
  execute_process(COMMAND h5dump -d /particles/id "${OUT}.d/snap_000000.h5"
                  RESULT_VARIABLE hrc OUTPUT_FILE "${OUT}.d/ids.txt" ERROR_VARIABLE herr)
  if(NOT hrc EQUAL 0)
    message(FATAL_ERROR "h5dump of the split's snapshot failed: ${herr}")
  endif()
  # the values after DATA {, each row's "(index):" left out
  execute_process(COMMAND python3 -c "import re,sys; t=open(sys.argv[1]).read(); d=re.sub(r'[(][0-9]+[)]:', ' ', t[t.index('DATA {'):]); v=sorted(int(x) for x in re.findall(r'[0-9]+', d)); sys.exit(0 if v == list(range(int(sys.argv[2]))) else 1)"
                          "${OUT}.d/ids.txt" ${particles}
                  RESULT_VARIABLE prc)
  if(NOT prc EQUAL 0)
    message(FATAL_ERROR "the split's snapshot does not hold each of the ${particles} particles once")
  endif()
  execute_process(COMMAND "${CLSPH}" render "${OUT}.d" --out "${OUT}.d/frames" --no-movie
                  RESULT_VARIABLE rrc OUTPUT_VARIABLE rout ERROR_VARIABLE rerr)
  if(NOT rrc EQUAL 0 OR NOT EXISTS "${OUT}.d/frames/frames/speed_000000.png")
    message(FATAL_ERROR "clsph render of the split's snapshot: ${rrc} ${rout}${rerr}")
  endif()
endif()
message("split on ${NP} ranks: ${steps} steps, positions ${dx_dr} dr and velocities ${dv_rel} from the whole run's, held ${held_ratio} times the particles")
