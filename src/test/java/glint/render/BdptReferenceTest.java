package glint.render;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The bidirectional integrator against the independent path tracer's images (src/test/resources/reference-pt),
 * within the bounds a correct path-traced render meets: caustic-lamp, whose caustic under the glass ball a
 * camera path finds only by chance, at its 1024 samples, and the scenes without caustic paths at 256.
 */
class BdptReferenceTest {

    @ParameterizedTest
    @CsvSource({"caustic-lamp, 1024, 0.043, 6.8", "bounce-box, 256, 3.3e-4, 1.24"})
    void matchesThePhysicallyBasedReferenceWithinTheBound(String name, int samples, double relMseBound,
                                                          double levelsBound) throws Exception {
        PathReferenceTest.assertWithinBound(LightTransport.BDPT, name, samples, relMseBound, levelsBound);
    }
}
