# Sourced by the scripts: Open MPI refuses to run as root without these,
# and must not bind two ranks to one core on small machines.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# Open MPI binds the ranks of every job to cores counted from core 0: two
# one-rank jobs side by side (a sweep beside a test, two cases of a study)
# then share core 0 and run at half speed while core 1 idles. Leave the
# placement to the kernel.
export OMPI_MCA_hwloc_base_binding_policy=none
