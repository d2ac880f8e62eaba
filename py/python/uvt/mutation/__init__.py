"""Mutation coverage of the committed vectors, MCY's way: Yosys ``mutate`` injects single
faults into each reference unit (``vectors/rtl``) at the builds of ``pnr.sh``'s table, all
behind one select input; one Verilator build of the unit's own bench runs every mutant against
the committed vector sets in the architectural mode a team's unit is checked in. ``python -m
uvt.mutation run`` writes ``host/report/mutation.json``; ``check`` reruns a fixed sample and
compares it with the committed results. It needs yosys, verilator (and iverilog for the
cross-check), not the compiled model."""
