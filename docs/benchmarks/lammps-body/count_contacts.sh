#!/bin/sh
# Print how many vertex-edge contacts PairBodyRoundedPolygon::compute() collected for the
# first pair, in Debian 12's LAMMPS (liblammps0 20220106.git7586adbb6a+ds1-2+b2, which
# reports "29 Sep 2021 - Update 2"). The offsets are that build's: 0x712 into compute() is
# the instruction after the second vertex_against_edge() call, where the int num_contacts
# sits at 0x164(%rsp). The array it counts into, contact_list, has room for 4.
#   ./count_contacts.sh data.minimal     -> num_contacts = 8, then stack smashing detected
#   ./count_contacts.sh data.control     -> num_contacts = 4
cd "$(dirname "$0")"
gdb -q -batch \
  -ex "set breakpoint pending on" \
  -ex "break LAMMPS_NS::PairBodyRoundedPolygon::compute" \
  -ex "run" -ex "delete" \
  -ex 'break *($pc + 0x712)' -ex "continue" \
  -ex 'printf "num_contacts = %d\n", *(int*)($rsp + 0x164)' \
  -ex "continue" \
  --args lmp -var data "${1:-data.minimal}" -in in.minimal -log none -nocite 2>&1 |
  grep -E "num_contacts =|stack smashing|Inferior 1"
