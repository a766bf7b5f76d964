# Answers with the slips a class makes: q1 with each rod's moment of inertia about its own
# centre (the parallel-axis term left out), q2 with H x Omega for Omega x H, q3 with a sign
# flipped, and q4 not answered.
q1 = "6 M/(m c^2)"
q2 = "-3 M/(16 c) + m c w^2/4"
q3 = "3 M/(8 c) + 3/8 m c w^2"
