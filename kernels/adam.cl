/* adam.cl: Adam updates of the fitter's parameters (Kingma & Ba 2015), on the device.
 *
 *     m ← β1 m + (1 − β1) g,  v ← β2 v + (1 − β2) g²,
 *     θ ← θ − lr · (m / (1 − β1^t)) / (sqrt(v / (1 − β2^t)) + ε)
 *
 * Keyframes are activated progressively, so each keyframe has its own step count t (0: not
 * active, the parameters are left alone; the host resets m and v when it activates one). The
 * host passes each keyframe's bias-correction denominators (1 − β1^t, 1 − β2^t), in float
 * as this kernel once computed them per element, (0, 0) for an inactive one: the same for every element of the
 * keyframe, so no work-item raises β to a power (a per-element power loop was most of this
 * kernel's time in a layered scene's fit). `first` skips keyframes below it (keyframe 0's
 * homography stays the identity). One work-item per element; `per_frame` elements per
 * keyframe.
 */
__kernel void adam(__global float* theta, __global const float* grad, __global float* m,
                   __global float* v, __global const float2* bias, int per_frame, int first,
                   float lr, float beta1, float beta2, float eps, int n) {
  const int i = get_global_id(0);
  if (i >= n) return;
  const int k = i / per_frame;
  const float2 c = bias[k];
  if (k < first || c.x == 0.0f) return;
  const float g = grad[i];
  const float mi = beta1 * m[i] + (1.0f - beta1) * g;
  const float vi = beta2 * v[i] + (1.0f - beta2) * g * g;
  m[i] = mi;
  v[i] = vi;
  const float mh = mi / c.x, vh = vi / c.y;
  theta[i] -= lr * mh / (sqrt(vh) + eps);
}
