# Generates the peer decks of Icpre 2 (docs/theory/brick8.md, eq. B-9c): a 100 x 20 x 20 mm Johnson-Cook cantilever
# of 2x2x2-point bricks, clamped at x = 0, its end pushed along Z at 5 mm/ms for 2 ms (bent well past yield), with
# the bar generator of generate_brick_decks.py. ICPRE18: Isolid 18 with Icpre blank, which the reference resolves to
# 2 with a plastic law; ICPRE14: Isolid 14, Icpre 2, twice as fine. Each folder's ref.extract is the reference
# solver's last row on its deck (run-or.sh, then or-extract.py). Run from this folder: python3 generate_icpre_decks.py
from generate_brick_decks import gen

if __name__ == "__main__":
    bent = dict(law="jc", v=5.0, tend=2.0, push="Z", print_every=100)
    gen("ICPRE18", "hex", isolid=18, **bent)
    gen("ICPRE14", "hex", isolid=14, icpre=2, nx=20, ny=2, nz=4, **bent)
