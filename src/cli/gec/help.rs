//! Long help of `pdesculpt gec fit` and `gec eval`: input formats and output.

pub const FORMATS: &str = "\
INPUT FORMATS (--input; JSON if the file starts with '[' or '{', CSV otherwise):
  CSV   one point per line, 'x,y' or 'x,y,z' (commas, or blanks/tabs/semicolons);
        every row has the same number of fields; an optional header line of
        names (e.g. 'x,y,z') as the first row; blank lines and lines starting
        with '#' are ignored, except that a line '# open' declares the
        polyline open (rejected).
  JSON  an array of points [[x, y], ...] or [[x, y, z], ...], or an object
        {\"points\": [...], \"closed\": true|false}; \"closed\": false declares
        the polyline open (rejected).
  2-column points lie in the plane z = 0.

THE POLYLINE must be closed, planar, with distinct points, in order along the
curve; the first point is not repeated at the end (a closing copy is dropped).
It is taken as OPEN, and rejected, when declared open or when the gap from
the last point back to the first is more than 10 times the median segment
and longer than every other segment (e.g. an arc missing a piece);
--assume-closed skips that test. Needs at least 2J+1 points.

PLANE: with --frame z (the default when every point has the same z) the
coefficients are in the input's x, y coordinates, as in the papers (z = z_c);
with --frame auto (default otherwise) the plane is fitted (Newell normal,
origin at the area centroid, e1 along the projection of X).

OUTPUT: ErM = max over input points of the distance to the fitted curve, ErA
= its mean (units of the input; *_rel: divided by the in-plane bounding-box
diagonal). -o writes the fitted curve as JSON {\"frame\": {\"origin\", \"e1\",
\"e2\"}, \"centre\": [x0, y0], \"x\": [[a_xn, b_xn], ...], \"y\": [[a_yn, b_yn],
...]} (x takes (cos, sin) pairs, y (sin, cos) pairs, angle theta in [0, 2 pi)),
the input of 'gec eval --gec' and of 'pde6 patch' sections.";

pub const EVAL_FORMATS: &str = "\
GEC.json: the file written by 'gec fit -o', or the JSON report of 'gec fit
--json' (its \"gec\" field). The parameter is the angle theta in [0, 2 pi)
(paper 002's v); with --turns it is paper 000's v in [0, 1] (theta = 2 pi v),
and derivatives are taken with respect to v.
Output: one line 't x y z' per parameter on stdout, or with --json
{\"derivative\": k, \"unit\": \"rad\"|\"turn\", \"points\": [{\"t\": t, \"value\": [x, y, z]}, ...]}.";
