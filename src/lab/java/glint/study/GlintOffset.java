package glint.study;

import glint.image.FrameBuffer;
import glint.render.RenderScene;
import glint.render.RenderSettings;
import glint.render.Shading;
import glint.render.Tracer;

/**
 * Glint's own offset rule, measured by rendering: a {@link ShadowScene} at one sample per pixel,
 * direct light only, with the given {@code epsilon} (offset epsilon x max(1, |p|) off a re-projected
 * hit point). With no ambient light and a black background a pixel is lit exactly when its red
 * channel is above zero.
 */
public final class GlintOffset {

    private GlintOffset() {
    }

    public static boolean[] lit(ShadowScene scene, double epsilon, Tracer tracer) {
        RenderScene compiled = RenderScene.compile(scene.toScene(),
                new RenderSettings(Shading.COOK_TORRANCE, 1, 0, epsilon));
        FrameBuffer frame = new FrameBuffer(scene.width(), scene.height());
        tracer.render(compiled, frame, 1, 0, 4);
        boolean[] lit = new boolean[scene.width() * scene.height()];
        float[] rgb = frame.rgb();
        for (int i = 0; i < lit.length; i++) {
            lit[i] = rgb[3 * i] > 0;
        }
        return lit;
    }
}
