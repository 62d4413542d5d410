# Writes the selective-mass-scaling peer case into OUT: the shared rail of SOURCE (../shared/peer-cases/rail_ishell1)
# with /AMS in its starter and /DT/AMS 0.67 1.5e-3 in its engine deck, and HERE's ref.extract and tolerances.
# cmake -DSOURCE=... -DHERE=... -DOUT=... -P make_case.cmake
file(READ ${SOURCE}/RAIL_0000.rad starter)
string(FIND "${starter}" "/END" end REVERSE)
if(end LESS 0)
  message(FATAL_ERROR "${SOURCE}/RAIL_0000.rad: no /END")
endif()
string(SUBSTRING "${starter}" 0 ${end} head)
string(SUBSTRING "${starter}" ${end} -1 tail)
file(MAKE_DIRECTORY ${OUT}/rail_ishell1_ams)
file(WRITE ${OUT}/rail_ishell1_ams/RAIL_0000.rad "${head}/AMS\n         0\n${tail}")
file(WRITE ${OUT}/rail_ishell1_ams/RAIL_0001.rad
     "#RADIOSS ENGINE\n/RUN/RAIL/1\n                   8\n/PRINT/-500\n/TFILE/4\n               0.016\n/DT/AMS/0\n                0.67              0.0015\n")
file(COPY ${HERE}/ref.extract ${HERE}/crumple-tolerances DESTINATION ${OUT}/rail_ishell1_ams)
