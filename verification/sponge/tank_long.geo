// The reference tank of the sponge verification (README.md): tank.geo with 6.9 m more beyond
// its end, 10 m in all, so that the wave's front, at sqrt(g h) = 1.21 m/s, reaches the end
// wall only after the runs end ((10 - 0.9) / 1.21 = 7.5 s): the end does not act on the gauge
// at all, neither by a reflected wave nor through the water's compression. The mesh up to
// x = 3.1 m is tank.geo's, so its gauge record is the short tanks' record without what their
// end sends back.
extension = 6.9;
Include "tank.geo";
