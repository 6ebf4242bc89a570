"""From measurements to a motion: the closed-form initial guess (Eq. (3)-(7)), the paper's refinement (Eq. (7)-(10)), the least-squares fit and the Cramér-Rao bounds."""
