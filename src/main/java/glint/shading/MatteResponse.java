package glint.shading;

/** A matte surface to Whitted's models: no single rays on, lit by the ambient light times its albedo. */
public final class MatteResponse implements WhittedResponse {

    @Override
    public void specular(Materials m, Surface s, SingleRays out) {
        out.setReflect(0, 0, 0);
        out.setTransmit(0, 0, 0);
    }

    @Override
    public boolean ambientLit() {
        return true;
    }
}
