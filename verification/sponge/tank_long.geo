// The reference tank of the sponge verification (README.md): tank.geo with 1.2 m more beyond
// its end, 4.3 m in all, so that the end wall's reflection reaches the gauge only after the
// runs end (5.4 s). The mesh up to x = 3.1 m is tank.geo's, so its gauge record is the
// short tanks' record without what their end sends back.
extension = 1.2;
Include "tank.geo";
