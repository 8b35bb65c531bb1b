import { resolveScene } from '../model/defaults';
import type { ImageFormat, SamplerName } from '../model/types';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';
import { ColorField } from './fields/ColorField';
import { ImageSizeFields } from './ImageSizeFields';
import { NumberField } from './fields/NumberField';
import { SelectField } from './fields/SelectField';
import { TextField } from './fields/TextField';

/** The samplers, simplest first (as the server's Sampler.names()). */
const SAMPLER_OPTIONS: { value: SamplerName; label: string; hint: string }[] = [
  { value: 'regular', label: 'Regular', hint: 'Cell centres; needs a square number of samples; aliases on fine patterns' },
  { value: 'random', label: 'Random', hint: 'Independent uniform samples; noisiest' },
  { value: 'jittered', label: 'Jittered', hint: 'One random sample in each cell of a grid' },
  { value: 'multijittered', label: 'Multi-jittered', hint: 'Jittered, and one sample in each narrow row and column too' },
  { value: 'sobol', label: 'Sobol (scrambled)', hint: 'Owen-scrambled Sobol points: stratified at every aspect ratio; best with a power of two' },
];

/** Scene-wide settings: name, background, ambient, output image and render quality. */
export function InspectorScene() {
  const scene = useSceneStore(selectDisplayScene);
  const s = useSceneStore.getState();
  const r = resolveScene(scene);
  return (
    <section className="inspector-section" aria-label="Scene settings" data-testid="inspector-scene">
      <h3>Scene</h3>
      <TextField label="Name" path="name" value={r.name} maxLength={200} hint="Default file name of the scene and of the rendered image" onCommit={s.setName} />
      <ColorField
        label="Background"
        path="background"
        value={r.background}
        hint="Colour of rays that hit nothing"
        onCommit={s.setBackground}
        onPreview={(background) => s.setPreview({ ...useSceneStore.getState().scene, background })}
        onPreviewEnd={s.cancelPreview}
      />
      <NumberField label="Ambient" path="ambient" value={r.ambient} min={0} max={1} step={0.01} hint="Ambient light in [0, 1], times each surface's diffuse colour" onCommit={s.setAmbient} />
      <fieldset className="inspector-group">
        <legend>Image</legend>
        <ImageSizeFields size={{ width: r.image.width, height: r.image.height }} onCommit={(size) => s.setImage(size)} />
        <SelectField
          label="Format"
          path="image.format"
          value={r.image.format}
          options={[
            { value: 'png', label: 'PNG (lossless)' },
            { value: 'jpg', label: 'JPEG' },
          ]}
          onCommit={(format) => s.setImage({ format: format as ImageFormat })}
        />
        {r.image.format === 'jpg' && (
          <NumberField label="JPEG quality" path="image.quality" value={r.image.quality} min={0} max={1} step={0.01} hint="0 to 1 (JPEG only)" onCommit={(quality) => s.setImage({ quality })} />
        )}
      </fieldset>
      <fieldset className="inspector-group">
        <legend>Render</legend>
        <SelectField
          label="Sampler"
          path="render.sampler"
          value={r.render.sampler}
          options={SAMPLER_OPTIONS}
          onCommit={(sampler) =>
            // the regular grid cannot sample adaptively: switching to it turns adaptive sampling off
            s.setRender(sampler === 'regular' ? { sampler, adaptive: 0 } : { sampler: sampler as SamplerName })
          }
        />
        <NumberField label="Samples per pixel" path="render.samples" value={r.render.samples} integer min={1} max={1024} step={1} hint="More samples: smoother edges, slower. With adaptive sampling: the most a pixel takes" onCommit={(samples) => s.setRender({ samples })} />
        <NumberField
          label="Adaptive threshold"
          path="render.adaptive"
          value={r.render.adaptive}
          min={0}
          max={1}
          step={0.01}
          hint="0: off. Otherwise a pixel stops taking samples once its estimated relative error is below this (with sobol from 1 sample, if its 8 neighbours agree; with the others from 8); 0.05 by default, smaller is smoother and slower; not with the regular sampler"
          onCommit={(adaptive) => s.setRender({ adaptive })}
        />
        <NumberField label="Max depth" path="render.maxDepth" value={r.render.maxDepth} integer min={0} max={16} step={1} hint="Reflection/refraction bounces" onCommit={(maxDepth) => s.setRender({ maxDepth })} />
        <NumberField label="Seed" path="render.seed" value={r.render.seed} integer step={1} hint="Varies the noise pattern; the same seed gives the same image" onCommit={(seed) => s.setRender({ seed })} />
      </fieldset>
    </section>
  );
}
