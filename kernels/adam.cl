/* adam.cl: Adam updates of the fitter's parameters (Kingma & Ba 2015), on the device.
 *
 *     m ← β1 m + (1 − β1) g,  v ← β2 v + (1 − β2) g²,
 *     θ ← θ − lr · (m / (1 − β1^t)) / (sqrt(v / (1 − β2^t)) + ε)
 *
 * Keyframes are activated progressively, so each keyframe has its own step count t (0: not
 * active, the parameters are left alone; the host resets m and v when it activates one).
 * `first` skips keyframes below it (keyframe 0's homography stays the identity). One
 * work-item per element; `per_frame` elements per keyframe.
 */
/* b^t for t >= 1 by repeated squaring: a few multiplies where PoCL's pown goes through exp
 * and log (a tenth of a layered scene's fit was pown). At most 2·log2(t) roundings, ~1e-6
 * relative for the fitter's t <= a few thousand: the bias corrections need no more. */
inline float power(float b, int t) {
  float r = 1.0f;
  while (t > 0) {
    if (t & 1) r *= b;
    b *= b;
    t >>= 1;
  }
  return r;
}

__kernel void adam(__global float* theta, __global const float* grad, __global float* m,
                   __global float* v, __global const int* steps, int per_frame, int first,
                   float lr, float beta1, float beta2, float eps, int n) {
  const int i = get_global_id(0);
  if (i >= n) return;
  const int k = i / per_frame;
  const int t = steps[k];
  if (k < first || t <= 0) return;
  const float g = grad[i];
  const float mi = beta1 * m[i] + (1.0f - beta1) * g;
  const float vi = beta2 * v[i] + (1.0f - beta2) * g * g;
  m[i] = mi;
  v[i] = vi;
  const float mh = mi / (1.0f - power(beta1, t)), vh = vi / (1.0f - power(beta2, t));
  theta[i] -= lr * mh / (sqrt(vh) + eps);
}
