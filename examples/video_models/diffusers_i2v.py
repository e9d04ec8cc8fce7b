#!/usr/bin/env python3
"""An image-to-video generator for svgmotion's `command` video plugin, on Hugging Face diffusers.

svgmotion runs this once per candidate (see diffusers.yaml next to it), never through a shell:

    python3 diffusers_i2v.py --image IMG --prompt TEXT --seed N --frames F --out OUT.mp4

It needs a machine with a CUDA GPU (about 24 GB for the default CogVideoX-5b-I2V weights at
bf16; fewer with --cpu-offload) and `pip install torch diffusers transformers accelerate
imageio imageio-ffmpeg`. It is documented, not run by the test suite: svgmotion's tests drive
the `command` plugin with a small script of ours instead.

Any image-to-video pipeline of diffusers with the (image, prompt, num_frames, generator) call
works the same way; pass its Hugging Face id as --model and its class as --pipeline.
"""
import argparse
import sys


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--image", required=True, help="the recoloured drawing (PNG)")
    ap.add_argument("--prompt", required=True, help="the full prompt (svgmotion fills its template)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--frames", type=int, default=49)
    ap.add_argument("--fps", type=int, default=8, help="frame rate written to the video")
    ap.add_argument("--out", required=True, help="the video to write (.mp4)")
    ap.add_argument("--model", default="THUDM/CogVideoX-5b-I2V")
    ap.add_argument("--pipeline", default="CogVideoXImageToVideoPipeline")
    ap.add_argument("--steps", type=int, default=50)
    ap.add_argument("--guidance", type=float, default=6.0)
    ap.add_argument("--cpu-offload", action="store_true", help="less GPU memory, slower")
    a = ap.parse_args()

    try:
        import torch
        import diffusers
        from diffusers.utils import export_to_video, load_image
    except ImportError as e:  # one line: svgmotion shows the log path with it
        print(f"diffusers_i2v: {e}; install torch, diffusers, transformers, accelerate, imageio-ffmpeg",
              file=sys.stderr)
        return 2

    cls = getattr(diffusers, a.pipeline, None)
    if cls is None:
        print(f"diffusers_i2v: diffusers has no pipeline class {a.pipeline}", file=sys.stderr)
        return 2
    device = "cuda" if torch.cuda.is_available() else "cpu"
    dtype = torch.bfloat16 if device == "cuda" else torch.float32
    pipe = cls.from_pretrained(a.model, torch_dtype=dtype)
    if a.cpu_offload and device == "cuda":
        pipe.enable_model_cpu_offload()
    else:
        pipe.to(device)

    image = load_image(a.image).convert("RGB")
    generator = torch.Generator(device=device).manual_seed(a.seed)
    frames = pipe(image=image, prompt=a.prompt, num_frames=a.frames, num_inference_steps=a.steps,
                  guidance_scale=a.guidance, generator=generator).frames[0]
    export_to_video(frames, a.out, fps=a.fps)
    return 0


if __name__ == "__main__":
    sys.exit(main())
