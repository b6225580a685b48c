/* trinormal 3D views (the explorer and the mesh view). Bundles three.js 0.187.0, three-mesh-bvh 0.9.17 and meshoptimizer 1.3.0 (MIT licences, see THIRD_PARTY_LICENSES.txt). Built by js/explorer/build.mjs. */
const G=globalThis.__trinormalExplorer||(globalThis.__trinormalExplorer={});
const R=G["e025a8c054570771"]||(G["e025a8c054570771"]=(()=>{var tnxModule=(()=>{var ql=Object.defineProperty;var xg=Object.getOwnPropertyDescriptor;var yg=Object.getOwnPropertyNames;var _g=Object.prototype.hasOwnProperty;var ha=(i,t,e)=>()=>{if(e)throw e[0];try{return i&&(t=i(i=0)),t}catch(n){throw e=[n],n}};var xu=(i,t)=>{for(var e in t)ql(i,e,{get:t[e],enumerable:!0})},vg=(i,t,e,n)=>{if(t&&typeof t=="object"||typeof t=="function")for(let a of yg(t))!_g.call(i,a)&&a!==e&&ql(i,a,{get:()=>t[a],enumerable:!(n=xg(t,a))||n.enumerable});return i};var Pa=i=>vg(ql({},"__esModule",{value:!0}),i);function Mg(i){for(let t=i.length-1;t>=0;--t)if(i[t]>=65535)return!0;return!1}function Sg(i){return ArrayBuffer.isView(i)&&!(i instanceof DataView)}function Qs(i){return document.createElementNS("http://www.w3.org/1999/xhtml",i)}function Uf(){let i=Qs("canvas");return i.style.display="block",i}function $s(...i){let t="THREE."+i.shift();Za?Za("log",t,...i):console.log(t,...i)}function Of(i){let t=i[0];if(typeof t=="string"&&t.startsWith("TSL:")){let e=i[1];e&&e.isStackTrace?i[0]+=" "+e.getLocation():i[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return i}function Ft(...i){i=Of(i);let t="THREE."+i.shift();if(Za)Za("warn",t,...i);else{let e=i[0];e&&e.isStackTrace?console.warn(e.getError(t)):console.warn(t,...i)}}function zt(...i){i=Of(i);let t="THREE."+i.shift();if(Za)Za("error",t,...i);else{let e=i[0];e&&e.isStackTrace?console.error(e.getError(t)):console.error(t,...i)}}function Xs(...i){let t=i.join(" ");t in yu||(yu[t]=!0,Ft(...i))}function Ff(i,t,e){return new Promise(function(n,a){function s(){switch(i.clientWaitSync(t,i.SYNC_FLUSH_COMMANDS_BIT,0)){case i.WAIT_FAILED:a();break;case i.TIMEOUT_EXPIRED:setTimeout(s,e);break;default:n()}}setTimeout(s,e)})}function Ji(){let i=Math.random()*4294967295|0,t=Math.random()*4294967295|0,e=Math.random()*4294967295|0,n=Math.random()*4294967295|0;return($e[i&255]+$e[i>>8&255]+$e[i>>16&255]+$e[i>>24&255]+"-"+$e[t&255]+$e[t>>8&255]+"-"+$e[t>>16&15|64]+$e[t>>24&255]+"-"+$e[e&63|128]+$e[e>>8&255]+"-"+$e[e>>16&255]+$e[e>>24&255]+$e[n&255]+$e[n>>8&255]+$e[n>>16&255]+$e[n>>24&255]).toLowerCase()}function Wt(i,t,e){return Math.max(t,Math.min(e,i))}function Qh(i,t){return(i%t+t)%t}function wg(i,t,e,n,a){return n+(i-t)*(a-n)/(e-t)}function Ag(i,t,e){return i!==t?(e-i)/(t-i):0}function Ys(i,t,e){return(1-e)*i+e*t}function Eg(i,t,e,n){return Ys(i,t,1-Math.exp(-e*n))}function Tg(i,t=1){return t-Math.abs(Qh(i,t*2)-t)}function Ig(i,t,e){return i<=t?0:i>=e?1:(i=(i-t)/(e-t),i*i*(3-2*i))}function Rg(i,t,e){return i<=t?0:i>=e?1:(i=(i-t)/(e-t),i*i*i*(i*(i*6-15)+10))}function Cg(i,t){return i+Math.floor(Math.random()*(t-i+1))}function Ng(i,t){return i+Math.random()*(t-i)}function Pg(i){return i*(.5-Math.random())}function Lg(i){i!==void 0&&(_u=i);let t=_u+=1831565813;return t=Math.imul(t^t>>>15,t|1),t^=t+Math.imul(t^t>>>7,t|61),((t^t>>>14)>>>0)/4294967296}function Dg(i){return i*qs}function Ug(i){return i*Qa}function Og(i){return i>0&&Number.isInteger(i)&&2**Math.round(Math.log2(i))===i}function Fg(i){return Math.pow(2,Math.ceil(Math.log(i)/Math.LN2))}function $h(i){return Math.pow(2,Math.floor(Math.log(i)/Math.LN2))}function Bg(i,t,e,n,a){let s=Math.cos,r=Math.sin,o=s(e/2),c=r(e/2),l=s((t+n)/2),h=r((t+n)/2),u=s((t-n)/2),d=r((t-n)/2),f=s((n-t)/2),x=r((n-t)/2);switch(a){case"XYX":i.set(o*h,c*u,c*d,o*l);break;case"YZY":i.set(c*d,o*h,c*u,o*l);break;case"ZXZ":i.set(c*u,c*d,o*h,o*l);break;case"XZX":i.set(o*h,c*x,c*f,o*l);break;case"YXY":i.set(c*f,o*h,c*x,o*l);break;case"ZYZ":i.set(c*x,c*f,o*h,o*l);break;default:Ft("MathUtils: .setQuaternionFromProperEuler() encountered an unknown order: "+a)}}function $c(i){switch(i.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function td(i,t){if(t.constructor===Float32Array)return i;let e=$c(t);if(e===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(i/e,-1)}function ed(i,t){if(t.constructor===Float32Array)return i;let e=$c(t);if(e===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(i*e)}function kg(){let i={enabled:!0,workingColorSpace:Ks,spaces:{},convert:function(a,s,r){return this.enabled===!1||s===r||!s||!r||(this.spaces[s].transfer===pe&&(a.r=Ai(a.r),a.g=Ai(a.g),a.b=Ai(a.b)),this.spaces[s].primaries!==this.spaces[r].primaries&&(a.applyMatrix3(this.spaces[s].toXYZ),a.applyMatrix3(this.spaces[r].fromXYZ)),this.spaces[r].transfer===pe&&(a.r=Ya(a.r),a.g=Ya(a.g),a.b=Ya(a.b))),a},workingToColorSpace:function(a,s){return this.convert(a,this.workingColorSpace,s)},colorSpaceToWorking:function(a,s){return this.convert(a,s,this.workingColorSpace)},getPrimaries:function(a){return this.spaces[a].primaries},getTransfer:function(a){return a===Li?Zs:this.spaces[a].transfer},getToneMappingMode:function(a){return this.spaces[a].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(a,s=this.workingColorSpace){return a.fromArray(this.spaces[s].luminanceCoefficients)},define:function(a){Object.assign(this.spaces,a)},_getMatrix:function(a,s,r){return a.copy(this.spaces[r].fromXYZ).multiply(this.spaces[s].toXYZ)},_getDrawingBufferColorSpace:function(a){return this.spaces[a].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(a=this.workingColorSpace){return this.spaces[a].workingColorSpaceConfig.unpackColorSpace}},t=[.64,.33,.3,.6,.15,.06],e=[.2126,.7152,.0722],n=[.3127,.329];return i.define({[Ks]:{primaries:t,whitePoint:n,transfer:Zs,toXYZ:Mu,fromXYZ:Su,luminanceCoefficients:e,workingColorSpaceConfig:{unpackColorSpace:Rn},outputColorSpaceConfig:{drawingBufferColorSpace:Rn}},[Rn]:{primaries:t,whitePoint:n,transfer:pe,toXYZ:Mu,fromXYZ:Su,luminanceCoefficients:e,outputColorSpaceConfig:{drawingBufferColorSpace:Rn}}}),i}function Ai(i){return i<.04045?i*.0773993808:Math.pow(i*.9478672986+.0521327014,2.4)}function Ya(i){return i<.0031308?i*12.92:1.055*Math.pow(i,.41666)-.055}function Kl(i){return typeof HTMLImageElement<"u"&&i instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&i instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&i instanceof ImageBitmap?Xo.getDataURL(i):i.data?{data:Array.from(i.data),width:i.width,height:i.height,type:i.data.constructor.name}:(Ft("Texture: Unable to serialize Texture."),{})}function $l(i,t,e){return e<0&&(e+=1),e>1&&(e-=1),e<1/6?i+(t-i)*6*e:e<1/2?t:e<2/3?i+(t-i)*6*(2/3-e):i}function oh(i,t,e,n,a){for(let s=0,r=i.length-3;s<=r;s+=3){ua.fromArray(i,s);let o=a.x*Math.abs(ua.x)+a.y*Math.abs(ua.y)+a.z*Math.abs(ua.z),c=t.dot(ua),l=e.dot(ua),h=n.dot(ua);if(Math.max(-Math.max(c,l,h),Math.min(c,l,h))>o)return!1}return!0}function Pu(i){return i.buffer._uuid===void 0&&(i.buffer._uuid=Ji()),i.byteOffset===0&&i.byteLength===i.buffer.byteLength?i.buffer._uuid:i.buffer._uuid+":"+i.byteOffset+":"+i.byteLength}function eb(i,t,e,n,a,s,r,o){let c;if(t.side===je?c=n.intersectTriangle(r,s,a,!0,o):c=n.intersectTriangle(a,s,r,t.side===ci,o),c===null)return null;vo.copy(o),vo.applyMatrix4(i.matrixWorld);let l=e.ray.origin.distanceTo(vo);return l<e.near||l>e.far?null:{distance:l,point:vo.clone(),object:i}}function Mo(i,t,e,n,a,s,r,o,c,l){i.getVertexPosition(o,bo),i.getVertexPosition(c,xo),i.getVertexPosition(l,yo);let h=eb(i,t,e,n,bo,xo,yo,Uu);if(h){let u=new z;ai.getBarycoord(Uu,bo,xo,yo,u),a&&(h.uv=ai.getInterpolatedAttribute(a,o,c,l,u,new Bt)),s&&(h.uv1=ai.getInterpolatedAttribute(s,o,c,l,u,new Bt)),r&&(h.normal=ai.getInterpolatedAttribute(r,o,c,l,u,new z),h.normal.dot(n.direction)>0&&h.normal.multiplyScalar(-1));let d={a:o,b:c,c:l,normal:new z,materialIndex:0};ai.getNormal(bo,xo,yo,d.normal),h.face=d,h.barycoord=u}return h}function fh(i,t){return i-t}function ib(i,t){return i.z-t.z}function ab(i,t){return t.z-i.z}function lb(i,t,e=0){let n=t.itemSize;if(i.isInterleavedBufferAttribute||i.array.constructor!==t.array.constructor){let a=i.count;for(let s=0;s<a;s++)for(let r=0;r<n;r++)t.setComponent(s+e,r,i.getComponent(s,r))}else t.array.set(i.array,e*n);t.needsUpdate=!0}function ni(i,t){if(i.constructor!==t.constructor){let e=Math.min(i.length,t.length);for(let n=0;n<e;n++)t[n]=i[n]}else{let e=Math.min(i.length,t.length);t.set(new i.constructor(i.buffer,0,e))}}function To(i,t,e,n,a,s,r){let o=i.geometry.attributes.position;if(Ko.fromBufferAttribute(o,a),Zo.fromBufferAttribute(o,s),e.distanceSqToSegment(Ko,Zo,gh,zu)>n)return;gh.applyMatrix4(i.matrixWorld);let l=t.ray.origin.distanceTo(gh);if(!(l<t.near||l>t.far))return{distance:l,point:zu.clone().applyMatrix4(i.matrixWorld),index:r,face:null,faceIndex:null,barycoord:null,object:i}}function Wu(i,t,e,n,a,s,r){let o=wh.distanceSqToPoint(i);if(o<e){let c=new z;wh.closestPointToPoint(i,c),c.applyMatrix4(n);let l=a.ray.origin.distanceTo(c);if(l<a.near||l>a.far)return;s.push({distance:l,distanceToRay:Math.sqrt(o),point:c,index:t,face:null,faceIndex:null,barycoord:null,object:r})}}function ju(i,t,e){let n=`${i.x},${i.y},${i.z}-${t.x},${t.y},${t.z}`,a=`${t.x},${t.y},${t.z}-${i.x},${i.y},${i.z}`;return e.has(n)===!0||e.has(a)===!0?!1:(e.add(n),e.add(a),!0)}function Aa(i){let t={};for(let e in i){t[e]={};for(let n in i[e]){let a=i[e][n];if(Xu(a))a.isRenderTargetTexture?(Ft("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),t[e][n]=null):t[e][n]=a.clone();else if(Array.isArray(a))if(Xu(a[0])){let s=[];for(let r=0,o=a.length;r<o;r++)s[r]=a[r].clone();t[e][n]=s}else t[e][n]=a.slice();else t[e][n]=a}}return t}function sn(i){let t={};for(let e=0;e<i.length;e++){let n=Aa(i[e]);for(let a in n)t[a]=n[a]}return t}function Xu(i){return i&&(i.isColor||i.isMatrix3||i.isMatrix4||i.isVector2||i.isVector3||i.isVector4||i.isTexture||i.isQuaternion)}function hb(i){let t=[];for(let e=0;e<i.length;e++)t.push(i[e].clone());return t}function nd(i){let t=i.getRenderTarget();return t===null?i.outputColorSpace:t.isXRRenderTarget===!0?t.texture.colorSpace:Kt.workingColorSpace}function Ga(i,t){return!i||i.constructor===t?i:typeof t.BYTES_PER_ELEMENT=="number"?new t(i):Array.prototype.slice.call(i)}function Co(i){return i!==void 0&&i.inTangents!==void 0&&i.outTangents!==void 0}function zf(i,t,e,n,a){let s=1-i;return s*s*s*t+3*s*s*i*e+3*s*i*i*n+i*i*i*a}function fb(i,t,e,n,a){let s=1-i;return 3*s*s*(e-t)+6*s*i*(n-e)+3*i*i*(a-n)}function pb(i,t,e,n,a){let s=(i-t)/(a-t);for(let r=0;r<8;r++){let o=zf(s,t,e,n,a)-i;if(Math.abs(o)<1e-10)break;let c=fb(s,t,e,n,a);if(Math.abs(c)<1e-10)break;s=Math.max(0,Math.min(1,s-o/c))}return s}function qu(i,t){for(let e=0,n=i.length;e!==n;e+=2)i[e]+=t}function Yu(i,t){for(let e=0,n=i.length;e!==n;e+=2)i[e]*=t}function tf(i,t){return i.distance-t.distance}function Th(i,t,e,n){let a=!0;if(i.layers.test(t.layers)&&i.raycast(t,e)===!1&&(a=!1),a===!0&&n===!0){let s=i.children;for(let r=0,o=s.length;r<o;r++)Th(s[r],t,e,!0)}}function sd(i,t,e,n){let a=Ab(n);switch(e){case jh:return i*t;case Nr:return i*t/a.components*a.byteLength;case Sa:return i*t/a.components*a.byteLength;case hi:return i*t*2/a.components*a.byteLength;case us:return i*t*2/a.components*a.byteLength;case Xh:return i*t*3/a.components*a.byteLength;case bn:return i*t*4/a.components*a.byteLength;case fs:return i*t*4/a.components*a.byteLength;case Pr:case Lr:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*8;case Dr:case Ur:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*16;case Sc:case Ac:return Math.max(i,16)*Math.max(t,8)/4;case Mc:case wc:return Math.max(i,8)*Math.max(t,8)/2;case Ec:case Tc:case Rc:case Cc:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*8;case Ic:case Or:case Nc:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*16;case Pc:return Math.floor((i+3)/4)*Math.floor((t+3)/4)*16;case Lc:return Math.floor((i+4)/5)*Math.floor((t+3)/4)*16;case Dc:return Math.floor((i+4)/5)*Math.floor((t+4)/5)*16;case Uc:return Math.floor((i+5)/6)*Math.floor((t+4)/5)*16;case Oc:return Math.floor((i+5)/6)*Math.floor((t+5)/6)*16;case Fc:return Math.floor((i+7)/8)*Math.floor((t+4)/5)*16;case Bc:return Math.floor((i+7)/8)*Math.floor((t+5)/6)*16;case kc:return Math.floor((i+7)/8)*Math.floor((t+7)/8)*16;case zc:return Math.floor((i+9)/10)*Math.floor((t+4)/5)*16;case Vc:return Math.floor((i+9)/10)*Math.floor((t+5)/6)*16;case Hc:return Math.floor((i+9)/10)*Math.floor((t+7)/8)*16;case Gc:return Math.floor((i+9)/10)*Math.floor((t+9)/10)*16;case Wc:return Math.floor((i+11)/12)*Math.floor((t+9)/10)*16;case jc:return Math.floor((i+11)/12)*Math.floor((t+11)/12)*16;case Xc:case qc:case Yc:return Math.ceil(i/4)*Math.ceil(t/4)*16;case Jc:case Kc:return Math.ceil(i/4)*Math.ceil(t/4)*8;case Fr:case Zc:return Math.ceil(i/4)*Math.ceil(t/4)*16}throw new Error(`Unable to determine texture byte length for ${e} format.`)}function Ab(i){switch(i){case an:case Rr:return{byteLength:1,components:1};case Yi:case Cr:case Zn:return{byteLength:2,components:1};case _c:case vc:return{byteLength:2,components:4};case An:case ds:case gn:return{byteLength:4,components:1};case Gh:case Wh:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${i}.`)}var mc,qi,oi,nf,Rh,af,Tr,sf,cs,ci,je,kn,ya,ls,Ch,Nh,Ph,rf,_a,of,cf,lf,hf,df,uf,ff,pf,Lh,Dh,mf,gf,bf,xf,yf,_f,vf,Mf,Sf,Oo,Fo,Bo,Ja,ko,zo,Vo,Ho,gc,wf,Af,li,Uh,Oh,Fh,Bh,kh,zh,Vh,Hh,va,hs,bc,xc,Go,si,Wo,De,Ef,Ir,mn,yc,Ni,an,Rr,Cr,Yi,ds,An,gn,Zn,_c,vc,Ma,Gh,Wh,jh,Xh,bn,Ti,Pi,Nr,Sa,hi,us,fs,Pr,Lr,Dr,Ur,Mc,Sc,wc,Ac,Ec,Tc,Ic,Rc,Cc,Or,Nc,Pc,Lc,Dc,Uc,Oc,Fc,Bc,kc,zc,Vc,Hc,Gc,Wc,jc,Xc,qc,Yc,Jc,Kc,Fr,Zc,Js,jo,Do,yh,_h,vh,Mh,Tf,Qc,If,Li,Rn,Ks,Zs,pe,Uo,Rf,Cf,Nf,Pf,qh,Lf,Df,Yh,Jh,Kh,Zh,Fn,Ka,yu,Za,Bf,Yn,$e,_u,qs,Qa,wa,rd,Bt,Cn,od,z,Yl,vu,cd,Vt,Jl,Mu,Su,Kt,La,Xo,zg,$a,Vg,Zl,wn,ld,ce,qo,Nn,tr,Yo,pc,oe,Da,jn,Hg,Gg,Bi,ro,Tn,wu,Au,Ii,ts,Wg,Eu,Ua,yi,oo,Vs,jg,Xg,Tu,Iu,Ru,Cu,qg,Oa,Ql,Fe,wi,Yg,es,kf,ki,co,jt,tn,er,Xn,_i,th,vi,Fa,Ba,Nu,eh,nh,ih,ah,sh,rh,ai,Oe,Mi,qn,lo,ka,za,Va,zi,Vi,da,Hs,ho,uo,ua,Le,fo,Jg,pn,nr,ir,xe,Kg,Gs,ch,Ge,Zg,On,lh,Ha,In,Ws,He,Ue,Jo,dn,Jn,hh,Qg,$g,un,tb,ri,Si,dh,po,mo,Kn,ns,Lu,fa,go,Du,bo,xo,yo,uh,_o,Uu,vo,nn,Ei,pa,nb,So,Ri,Ou,ar,Sh,Sn,sb,rb,ob,wo,ma,ph,Fu,Bu,cb,mh,en,Ao,sr,ga,Ko,Zo,ku,js,Eo,gh,zu,ba,Vu,Hu,is,rr,Qo,Gu,wh,Io,Ro,or,cr,Ci,lr,hr,as,ss,dr,ur,fr,pr,mr,Br,db,ub,Bn,$o,gr,tc,ec,Gi,nc,ic,ac,sc,Pn,Wi,rc,oc,cc,br,ji,lc,hc,Vf,dc,xr,bh,Ju,Ku,uc,No,Po,ii,yr,Hi,Zu,Qu,fn,_r,Ah,vr,Mr,Sr,Wa,ja,rs,fc,id,mb,ad,gb,bb,xb,yb,_b,vb,Mb,Eh,we,zM,Xi,$u,wr,os,hd,Ih,ef,Lo,Xa,qa,xh,Sb,wb,xa,Ar,Er,dd=ha(()=>{mc="187",qi={LEFT:0,MIDDLE:1,RIGHT:2,ROTATE:0,DOLLY:1,PAN:2},oi={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},nf=0,Rh=1,af=2,Tr=1,sf=2,cs=3,ci=0,je=1,kn=2,ya=0,ls=1,Ch=2,Nh=3,Ph=4,rf=5,_a=100,of=101,cf=102,lf=103,hf=104,df=200,uf=201,ff=202,pf=203,Lh=204,Dh=205,mf=206,gf=207,bf=208,xf=209,yf=210,_f=211,vf=212,Mf=213,Sf=214,Oo=0,Fo=1,Bo=2,Ja=3,ko=4,zo=5,Vo=6,Ho=7,gc=0,wf=1,Af=2,li=0,Uh=1,Oh=2,Fh=3,Bh=4,kh=5,zh=6,Vh=7,Hh=300,va=301,hs=302,bc=303,xc=304,Go=1e3,si=1001,Wo=1002,De=1003,Ef=1004,Ir=1005,mn=1006,yc=1007,Ni=1008,an=1009,Rr=1010,Cr=1011,Yi=1012,ds=1013,An=1014,gn=1015,Zn=1016,_c=1017,vc=1018,Ma=1020,Gh=35902,Wh=35899,jh=1021,Xh=1022,bn=1023,Ti=1026,Pi=1027,Nr=1028,Sa=1029,hi=1030,us=1031,fs=1033,Pr=33776,Lr=33777,Dr=33778,Ur=33779,Mc=35840,Sc=35841,wc=35842,Ac=35843,Ec=36196,Tc=37492,Ic=37496,Rc=37488,Cc=37489,Or=37490,Nc=37491,Pc=37808,Lc=37809,Dc=37810,Uc=37811,Oc=37812,Fc=37813,Bc=37814,kc=37815,zc=37816,Vc=37817,Hc=37818,Gc=37819,Wc=37820,jc=37821,Xc=36492,qc=36494,Yc=36495,Jc=36283,Kc=36284,Fr=36285,Zc=36286,Js=2300,jo=2301,Do=2302,yh=2303,_h=2400,vh=2401,Mh=2402,Tf=3200,Qc=0,If=1,Li="",Rn="srgb",Ks="srgb-linear",Zs="linear",pe="srgb",Uo=7680,Rf=519,Cf=512,Nf=513,Pf=514,qh=515,Lf=516,Df=517,Yh=518,Jh=519,Kh=35044,Zh="300 es",Fn=2e3,Ka=2001;yu={},Za=null;Bf={[Oo]:Oo,[Bo]:Vo,[ko]:ko,[Ja]:zo,[Fo]:Fo,[Vo]:Bo,[Ho]:Ho,[zo]:Ja},Yn=class{addEventListener(t,e){this._listeners===void 0&&(this._listeners={});let n=this._listeners;n[t]===void 0&&(n[t]=[]),n[t].indexOf(e)===-1&&n[t].push(e)}hasEventListener(t,e){let n=this._listeners;return n===void 0?!1:n[t]!==void 0&&n[t].indexOf(e)!==-1}removeEventListener(t,e){let n=this._listeners;if(n===void 0)return;let a=n[t];if(a!==void 0){let s=a.indexOf(e);s!==-1&&a.splice(s,1)}}dispatchEvent(t){let e=this._listeners;if(e===void 0)return;let n=e[t.type];if(n!==void 0){t.target=this;let a=n.slice(0);for(let s=0,r=a.length;s<r;s++)a[s].call(this,t);t.target=null}}},$e=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],_u=1234567,qs=Math.PI/180,Qa=180/Math.PI;wa={DEG2RAD:qs,RAD2DEG:Qa,generateUUID:Ji,clamp:Wt,euclideanModulo:Qh,mapLinear:wg,inverseLerp:Ag,lerp:Ys,damp:Eg,pingpong:Tg,smoothstep:Ig,smootherstep:Rg,randInt:Cg,randFloat:Ng,randFloatSpread:Pg,seededRandom:Lg,degToRad:Dg,radToDeg:Ug,isPowerOfTwo:Og,ceilPowerOfTwo:Fg,floorPowerOfTwo:$h,setQuaternionFromProperEuler:Bg,normalize:ed,denormalize:td},rd=class rd{constructor(t=0,e=0){this.x=t,this.y=e}get width(){return this.x}set width(t){this.x=t}get height(){return this.y}set height(t){this.y=t}set(t,e){return this.x=t,this.y=e,this}setScalar(t){return this.x=t,this.y=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;default:throw new Error("THREE.Vector2: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y)}copy(t){return this.x=t.x,this.y=t.y,this}add(t){return this.x+=t.x,this.y+=t.y,this}addScalar(t){return this.x+=t,this.y+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this}subScalar(t){return this.x-=t,this.y-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this}multiply(t){return this.x*=t.x,this.y*=t.y,this}multiplyScalar(t){return this.x*=t,this.y*=t,this}divide(t){return this.x/=t.x,this.y/=t.y,this}divideScalar(t){return this.multiplyScalar(1/t)}applyMatrix3(t){let e=this.x,n=this.y,a=t.elements;return this.x=a[0]*e+a[3]*n+a[6],this.y=a[1]*e+a[4]*n+a[7],this}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this}clamp(t,e){return this.x=Wt(this.x,t.x,e.x),this.y=Wt(this.y,t.y,e.y),this}clampScalar(t,e){return this.x=Wt(this.x,t,e),this.y=Wt(this.y,t,e),this}clampLength(t,e){let n=this.length();return this.divideScalar(n||1).multiplyScalar(Wt(n,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(t){return this.x*t.x+this.y*t.y}cross(t){return this.x*t.y-this.y*t.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(t){let e=Math.sqrt(this.lengthSq()*t.lengthSq());if(e===0)return Math.PI/2;let n=this.dot(t)/e;return Math.acos(Wt(n,-1,1))}distanceTo(t){return Math.sqrt(this.distanceToSquared(t))}distanceToSquared(t){let e=this.x-t.x,n=this.y-t.y;return e*e+n*n}manhattanDistanceTo(t){return Math.abs(this.x-t.x)+Math.abs(this.y-t.y)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this}lerpVectors(t,e,n){return this.x=t.x+(e.x-t.x)*n,this.y=t.y+(e.y-t.y)*n,this}equals(t){return t.x===this.x&&t.y===this.y}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this}rotateAround(t,e){let n=Math.cos(e),a=Math.sin(e),s=this.x-t.x,r=this.y-t.y;return this.x=s*n-r*a+t.x,this.y=s*a+r*n+t.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}};rd.prototype.isVector2=!0;Bt=rd,Cn=class{constructor(t=0,e=0,n=0,a=1){this.isQuaternion=!0,this._x=t,this._y=e,this._z=n,this._w=a}static slerpFlat(t,e,n,a,s,r,o){let c=n[a+0],l=n[a+1],h=n[a+2],u=n[a+3],d=s[r+0],f=s[r+1],x=s[r+2],v=s[r+3];if(u!==v||c!==d||l!==f||h!==x){let m=c*d+l*f+h*x+u*v;m<0&&(d=-d,f=-f,x=-x,v=-v,m=-m);let g=1-o;if(m<.9995){let y=Math.acos(m),w=Math.sin(y);g=Math.sin(g*y)/w,o=Math.sin(o*y)/w,c=c*g+d*o,l=l*g+f*o,h=h*g+x*o,u=u*g+v*o}else{c=c*g+d*o,l=l*g+f*o,h=h*g+x*o,u=u*g+v*o;let y=1/Math.sqrt(c*c+l*l+h*h+u*u);c*=y,l*=y,h*=y,u*=y}}t[e]=c,t[e+1]=l,t[e+2]=h,t[e+3]=u}static multiplyQuaternionsFlat(t,e,n,a,s,r){let o=n[a],c=n[a+1],l=n[a+2],h=n[a+3],u=s[r],d=s[r+1],f=s[r+2],x=s[r+3];return t[e]=o*x+h*u+c*f-l*d,t[e+1]=c*x+h*d+l*u-o*f,t[e+2]=l*x+h*f+o*d-c*u,t[e+3]=h*x-o*u-c*d-l*f,t}get x(){return this._x}set x(t){this._x=t,this._onChangeCallback()}get y(){return this._y}set y(t){this._y=t,this._onChangeCallback()}get z(){return this._z}set z(t){this._z=t,this._onChangeCallback()}get w(){return this._w}set w(t){this._w=t,this._onChangeCallback()}set(t,e,n,a){return this._x=t,this._y=e,this._z=n,this._w=a,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(t){return this._x=t.x,this._y=t.y,this._z=t.z,this._w=t.w,this._onChangeCallback(),this}setFromEuler(t,e=!0){let n=t._x,a=t._y,s=t._z,r=t._order,o=Math.cos,c=Math.sin,l=o(n/2),h=o(a/2),u=o(s/2),d=c(n/2),f=c(a/2),x=c(s/2);switch(r){case"XYZ":this._x=d*h*u+l*f*x,this._y=l*f*u-d*h*x,this._z=l*h*x+d*f*u,this._w=l*h*u-d*f*x;break;case"YXZ":this._x=d*h*u+l*f*x,this._y=l*f*u-d*h*x,this._z=l*h*x-d*f*u,this._w=l*h*u+d*f*x;break;case"ZXY":this._x=d*h*u-l*f*x,this._y=l*f*u+d*h*x,this._z=l*h*x+d*f*u,this._w=l*h*u-d*f*x;break;case"ZYX":this._x=d*h*u-l*f*x,this._y=l*f*u+d*h*x,this._z=l*h*x-d*f*u,this._w=l*h*u+d*f*x;break;case"YZX":this._x=d*h*u+l*f*x,this._y=l*f*u+d*h*x,this._z=l*h*x-d*f*u,this._w=l*h*u-d*f*x;break;case"XZY":this._x=d*h*u-l*f*x,this._y=l*f*u-d*h*x,this._z=l*h*x+d*f*u,this._w=l*h*u+d*f*x;break;default:Ft("Quaternion: .setFromEuler() encountered an unknown order: "+r)}return e===!0&&this._onChangeCallback(),this}setFromAxisAngle(t,e){let n=e/2,a=Math.sin(n);return this._x=t.x*a,this._y=t.y*a,this._z=t.z*a,this._w=Math.cos(n),this._onChangeCallback(),this}setFromRotationMatrix(t){let e=t.elements,n=e[0],a=e[4],s=e[8],r=e[1],o=e[5],c=e[9],l=e[2],h=e[6],u=e[10],d=n+o+u;if(d>0){let f=.5/Math.sqrt(d+1);this._w=.25/f,this._x=(h-c)*f,this._y=(s-l)*f,this._z=(r-a)*f}else if(n>o&&n>u){let f=2*Math.sqrt(1+n-o-u);this._w=(h-c)/f,this._x=.25*f,this._y=(a+r)/f,this._z=(s+l)/f}else if(o>u){let f=2*Math.sqrt(1+o-n-u);this._w=(s-l)/f,this._x=(a+r)/f,this._y=.25*f,this._z=(c+h)/f}else{let f=2*Math.sqrt(1+u-n-o);this._w=(r-a)/f,this._x=(s+l)/f,this._y=(c+h)/f,this._z=.25*f}return this._onChangeCallback(),this}setFromUnitVectors(t,e){let n=t.dot(e)+1;return n<1e-8?(n=0,Math.abs(t.x)>Math.abs(t.z)?(this._x=-t.y,this._y=t.x,this._z=0,this._w=n):(this._x=0,this._y=-t.z,this._z=t.y,this._w=n)):(this._x=t.y*e.z-t.z*e.y,this._y=t.z*e.x-t.x*e.z,this._z=t.x*e.y-t.y*e.x,this._w=n),this.normalize()}angleTo(t){return 2*Math.acos(Math.abs(Wt(this.dot(t),-1,1)))}rotateTowards(t,e){let n=this.angleTo(t);if(n===0)return this;let a=Math.min(1,e/n);return this.slerp(t,a),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(t){return this._x*t._x+this._y*t._y+this._z*t._z+this._w*t._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let t=this.length();return t===0?(this._x=0,this._y=0,this._z=0,this._w=1):(t=1/t,this._x=this._x*t,this._y=this._y*t,this._z=this._z*t,this._w=this._w*t),this._onChangeCallback(),this}multiply(t){return this.multiplyQuaternions(this,t)}premultiply(t){return this.multiplyQuaternions(t,this)}multiplyQuaternions(t,e){let n=t._x,a=t._y,s=t._z,r=t._w,o=e._x,c=e._y,l=e._z,h=e._w;return this._x=n*h+r*o+a*l-s*c,this._y=a*h+r*c+s*o-n*l,this._z=s*h+r*l+n*c-a*o,this._w=r*h-n*o-a*c-s*l,this._onChangeCallback(),this}slerp(t,e){let n=t._x,a=t._y,s=t._z,r=t._w,o=this.dot(t);o<0&&(n=-n,a=-a,s=-s,r=-r,o=-o);let c=1-e;if(o<.9995){let l=Math.acos(o),h=Math.sin(l);c=Math.sin(c*l)/h,e=Math.sin(e*l)/h,this._x=this._x*c+n*e,this._y=this._y*c+a*e,this._z=this._z*c+s*e,this._w=this._w*c+r*e,this._onChangeCallback()}else this._x=this._x*c+n*e,this._y=this._y*c+a*e,this._z=this._z*c+s*e,this._w=this._w*c+r*e,this.normalize();return this}slerpQuaternions(t,e,n){return this.copy(t).slerp(e,n)}random(){let t=2*Math.PI*Math.random(),e=2*Math.PI*Math.random(),n=Math.random(),a=Math.sqrt(1-n),s=Math.sqrt(n);return this.set(a*Math.sin(t),a*Math.cos(t),s*Math.sin(e),s*Math.cos(e))}equals(t){return t._x===this._x&&t._y===this._y&&t._z===this._z&&t._w===this._w}fromArray(t,e=0){return this._x=t[e],this._y=t[e+1],this._z=t[e+2],this._w=t[e+3],this._onChangeCallback(),this}toArray(t=[],e=0){return t[e]=this._x,t[e+1]=this._y,t[e+2]=this._z,t[e+3]=this._w,t}fromBufferAttribute(t,e){return this._x=t.getX(e),this._y=t.getY(e),this._z=t.getZ(e),this._w=t.getW(e),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(t){return this._onChangeCallback=t,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}},od=class od{constructor(t=0,e=0,n=0){this.x=t,this.y=e,this.z=n}set(t,e,n){return n===void 0&&(n=this.z),this.x=t,this.y=e,this.z=n,this}setScalar(t){return this.x=t,this.y=t,this.z=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setZ(t){return this.z=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;case 2:this.z=e;break;default:throw new Error("THREE.Vector3: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(t){return this.x=t.x,this.y=t.y,this.z=t.z,this}add(t){return this.x+=t.x,this.y+=t.y,this.z+=t.z,this}addScalar(t){return this.x+=t,this.y+=t,this.z+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this.z=t.z+e.z,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this.z+=t.z*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this.z-=t.z,this}subScalar(t){return this.x-=t,this.y-=t,this.z-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this.z=t.z-e.z,this}multiply(t){return this.x*=t.x,this.y*=t.y,this.z*=t.z,this}multiplyScalar(t){return this.x*=t,this.y*=t,this.z*=t,this}multiplyVectors(t,e){return this.x=t.x*e.x,this.y=t.y*e.y,this.z=t.z*e.z,this}applyEuler(t){return this.applyQuaternion(vu.setFromEuler(t))}applyAxisAngle(t,e){return this.applyQuaternion(vu.setFromAxisAngle(t,e))}applyMatrix3(t){let e=this.x,n=this.y,a=this.z,s=t.elements;return this.x=s[0]*e+s[3]*n+s[6]*a,this.y=s[1]*e+s[4]*n+s[7]*a,this.z=s[2]*e+s[5]*n+s[8]*a,this}applyNormalMatrix(t){return this.applyMatrix3(t).normalize()}applyMatrix4(t){let e=this.x,n=this.y,a=this.z,s=t.elements,r=1/(s[3]*e+s[7]*n+s[11]*a+s[15]);return this.x=(s[0]*e+s[4]*n+s[8]*a+s[12])*r,this.y=(s[1]*e+s[5]*n+s[9]*a+s[13])*r,this.z=(s[2]*e+s[6]*n+s[10]*a+s[14])*r,this}applyQuaternion(t){let e=this.x,n=this.y,a=this.z,s=t.x,r=t.y,o=t.z,c=t.w,l=2*(r*a-o*n),h=2*(o*e-s*a),u=2*(s*n-r*e);return this.x=e+c*l+r*u-o*h,this.y=n+c*h+o*l-s*u,this.z=a+c*u+s*h-r*l,this}project(t){return this.applyMatrix4(t.matrixWorldInverse).applyMatrix4(t.projectionMatrix)}unproject(t){return this.applyMatrix4(t.projectionMatrixInverse).applyMatrix4(t.matrixWorld)}transformDirection(t){let e=this.x,n=this.y,a=this.z,s=t.elements;return this.x=s[0]*e+s[4]*n+s[8]*a,this.y=s[1]*e+s[5]*n+s[9]*a,this.z=s[2]*e+s[6]*n+s[10]*a,this.normalize()}divide(t){return this.x/=t.x,this.y/=t.y,this.z/=t.z,this}divideScalar(t){return this.multiplyScalar(1/t)}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this.z=Math.min(this.z,t.z),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this.z=Math.max(this.z,t.z),this}clamp(t,e){return this.x=Wt(this.x,t.x,e.x),this.y=Wt(this.y,t.y,e.y),this.z=Wt(this.z,t.z,e.z),this}clampScalar(t,e){return this.x=Wt(this.x,t,e),this.y=Wt(this.y,t,e),this.z=Wt(this.z,t,e),this}clampLength(t,e){let n=this.length();return this.divideScalar(n||1).multiplyScalar(Wt(n,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(t){return this.x*t.x+this.y*t.y+this.z*t.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this.z+=(t.z-this.z)*e,this}lerpVectors(t,e,n){return this.x=t.x+(e.x-t.x)*n,this.y=t.y+(e.y-t.y)*n,this.z=t.z+(e.z-t.z)*n,this}cross(t){return this.crossVectors(this,t)}crossVectors(t,e){let n=t.x,a=t.y,s=t.z,r=e.x,o=e.y,c=e.z;return this.x=a*c-s*o,this.y=s*r-n*c,this.z=n*o-a*r,this}projectOnVector(t){let e=t.lengthSq();if(e===0)return this.set(0,0,0);let n=t.dot(this)/e;return this.copy(t).multiplyScalar(n)}projectOnPlane(t){return Yl.copy(this).projectOnVector(t),this.sub(Yl)}reflect(t){return this.sub(Yl.copy(t).multiplyScalar(2*this.dot(t)))}angleTo(t){let e=Math.sqrt(this.lengthSq()*t.lengthSq());if(e===0)return Math.PI/2;let n=this.dot(t)/e;return Math.acos(Wt(n,-1,1))}distanceTo(t){return Math.sqrt(this.distanceToSquared(t))}distanceToSquared(t){let e=this.x-t.x,n=this.y-t.y,a=this.z-t.z;return e*e+n*n+a*a}manhattanDistanceTo(t){return Math.abs(this.x-t.x)+Math.abs(this.y-t.y)+Math.abs(this.z-t.z)}setFromSpherical(t){return this.setFromSphericalCoords(t.radius,t.phi,t.theta)}setFromSphericalCoords(t,e,n){let a=Math.sin(e)*t;return this.x=a*Math.sin(n),this.y=Math.cos(e)*t,this.z=a*Math.cos(n),this}setFromCylindrical(t){return this.setFromCylindricalCoords(t.radius,t.theta,t.y)}setFromCylindricalCoords(t,e,n){return this.x=t*Math.sin(e),this.y=n,this.z=t*Math.cos(e),this}setFromMatrixPosition(t){let e=t.elements;return this.x=e[12],this.y=e[13],this.z=e[14],this}setFromMatrixScale(t){let e=this.setFromMatrixColumn(t,0).length(),n=this.setFromMatrixColumn(t,1).length(),a=this.setFromMatrixColumn(t,2).length();return this.x=e,this.y=n,this.z=a,this}setFromMatrixColumn(t,e){return this.fromArray(t.elements,e*4)}setFromMatrix3Column(t,e){return this.fromArray(t.elements,e*3)}setFromEuler(t){return this.x=t._x,this.y=t._y,this.z=t._z,this}setFromColor(t){return this.x=t.r,this.y=t.g,this.z=t.b,this}equals(t){return t.x===this.x&&t.y===this.y&&t.z===this.z}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this.z=t[e+2],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t[e+2]=this.z,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this.z=t.getZ(e),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){let t=Math.random()*Math.PI*2,e=Math.random()*2-1,n=Math.sqrt(1-e*e);return this.x=n*Math.cos(t),this.y=e,this.z=n*Math.sin(t),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}};od.prototype.isVector3=!0;z=od,Yl=new z,vu=new Cn,cd=class cd{constructor(t,e,n,a,s,r,o,c,l){this.elements=[1,0,0,0,1,0,0,0,1],t!==void 0&&this.set(t,e,n,a,s,r,o,c,l)}set(t,e,n,a,s,r,o,c,l){let h=this.elements;return h[0]=t,h[1]=a,h[2]=o,h[3]=e,h[4]=s,h[5]=c,h[6]=n,h[7]=r,h[8]=l,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(t){let e=this.elements,n=t.elements;return e[0]=n[0],e[1]=n[1],e[2]=n[2],e[3]=n[3],e[4]=n[4],e[5]=n[5],e[6]=n[6],e[7]=n[7],e[8]=n[8],this}extractBasis(t,e,n){return t.setFromMatrix3Column(this,0),e.setFromMatrix3Column(this,1),n.setFromMatrix3Column(this,2),this}setFromMatrix4(t){let e=t.elements;return this.set(e[0],e[4],e[8],e[1],e[5],e[9],e[2],e[6],e[10]),this}multiply(t){return this.multiplyMatrices(this,t)}premultiply(t){return this.multiplyMatrices(t,this)}multiplyMatrices(t,e){let n=t.elements,a=e.elements,s=this.elements,r=n[0],o=n[3],c=n[6],l=n[1],h=n[4],u=n[7],d=n[2],f=n[5],x=n[8],v=a[0],m=a[3],g=a[6],y=a[1],w=a[4],p=a[7],_=a[2],S=a[5],b=a[8];return s[0]=r*v+o*y+c*_,s[3]=r*m+o*w+c*S,s[6]=r*g+o*p+c*b,s[1]=l*v+h*y+u*_,s[4]=l*m+h*w+u*S,s[7]=l*g+h*p+u*b,s[2]=d*v+f*y+x*_,s[5]=d*m+f*w+x*S,s[8]=d*g+f*p+x*b,this}multiplyScalar(t){let e=this.elements;return e[0]*=t,e[3]*=t,e[6]*=t,e[1]*=t,e[4]*=t,e[7]*=t,e[2]*=t,e[5]*=t,e[8]*=t,this}determinant(){let t=this.elements,e=t[0],n=t[1],a=t[2],s=t[3],r=t[4],o=t[5],c=t[6],l=t[7],h=t[8];return e*r*h-e*o*l-n*s*h+n*o*c+a*s*l-a*r*c}invert(){let t=this.elements,e=t[0],n=t[1],a=t[2],s=t[3],r=t[4],o=t[5],c=t[6],l=t[7],h=t[8],u=h*r-o*l,d=o*c-h*s,f=l*s-r*c,x=e*u+n*d+a*f;if(x===0)return this.set(0,0,0,0,0,0,0,0,0);let v=1/x;return t[0]=u*v,t[1]=(a*l-h*n)*v,t[2]=(o*n-a*r)*v,t[3]=d*v,t[4]=(h*e-a*c)*v,t[5]=(a*s-o*e)*v,t[6]=f*v,t[7]=(n*c-l*e)*v,t[8]=(r*e-n*s)*v,this}transpose(){let t,e=this.elements;return t=e[1],e[1]=e[3],e[3]=t,t=e[2],e[2]=e[6],e[6]=t,t=e[5],e[5]=e[7],e[7]=t,this}getNormalMatrix(t){return this.setFromMatrix4(t).invert().transpose()}transposeIntoArray(t){let e=this.elements;return t[0]=e[0],t[1]=e[3],t[2]=e[6],t[3]=e[1],t[4]=e[4],t[5]=e[7],t[6]=e[2],t[7]=e[5],t[8]=e[8],this}setUvTransform(t,e,n,a,s,r,o){let c=Math.cos(s),l=Math.sin(s);return this.set(n*c,n*l,-n*(c*r+l*o)+r+t,-a*l,a*c,-a*(-l*r+c*o)+o+e,0,0,1),this}scale(t,e){return Xs("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(Jl.makeScale(t,e)),this}rotate(t){return Xs("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(Jl.makeRotation(-t)),this}translate(t,e){return Xs("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(Jl.makeTranslation(t,e)),this}makeTranslation(t,e){return t.isVector2?this.set(1,0,t.x,0,1,t.y,0,0,1):this.set(1,0,t,0,1,e,0,0,1),this}makeRotation(t){let e=Math.cos(t),n=Math.sin(t);return this.set(e,-n,0,n,e,0,0,0,1),this}makeScale(t,e){return this.set(t,0,0,0,e,0,0,0,1),this}equals(t){let e=this.elements,n=t.elements;for(let a=0;a<9;a++)if(e[a]!==n[a])return!1;return!0}fromArray(t,e=0){for(let n=0;n<9;n++)this.elements[n]=t[n+e];return this}toArray(t=[],e=0){let n=this.elements;return t[e]=n[0],t[e+1]=n[1],t[e+2]=n[2],t[e+3]=n[3],t[e+4]=n[4],t[e+5]=n[5],t[e+6]=n[6],t[e+7]=n[7],t[e+8]=n[8],t}clone(){return new this.constructor().fromArray(this.elements)}};cd.prototype.isMatrix3=!0;Vt=cd,Jl=new Vt,Mu=new Vt().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),Su=new Vt().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);Kt=kg();Xo=class{static getDataURL(t,e="image/png"){if(/^data:/i.test(t.src)||typeof HTMLCanvasElement>"u")return t.src;let n;if(t instanceof HTMLCanvasElement)n=t;else{La===void 0&&(La=Qs("canvas")),La.width=t.width,La.height=t.height;let a=La.getContext("2d");t instanceof ImageData?a.putImageData(t,0,0):a.drawImage(t,0,0,t.width,t.height),n=La}return n.toDataURL(e)}static sRGBToLinear(t){if(typeof HTMLImageElement<"u"&&t instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&t instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&t instanceof ImageBitmap){let e=Qs("canvas");e.width=t.width,e.height=t.height;let n=e.getContext("2d");n.drawImage(t,0,0,t.width,t.height);let a=n.getImageData(0,0,t.width,t.height),s=a.data;for(let r=0;r<s.length;r++)s[r]=Ai(s[r]/255)*255;return n.putImageData(a,0,0),e}else if(t.data){let e=t.data.slice(0);for(let n=0;n<e.length;n++)e instanceof Uint8Array||e instanceof Uint8ClampedArray?e[n]=Math.floor(Ai(e[n]/255)*255):e[n]=Ai(e[n]);return{data:e,width:t.width,height:t.height}}else return Ft("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),t}},zg=0,$a=class{constructor(t=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:zg++}),this.uuid=Ji(),this.data=t,this.dataReady=!0,this.version=0}getSize(t){let e=this.data;return typeof HTMLVideoElement<"u"&&e instanceof HTMLVideoElement?t.set(e.videoWidth,e.videoHeight,0):typeof VideoFrame<"u"&&e instanceof VideoFrame?t.set(e.displayWidth,e.displayHeight,0):e!==null?t.set(e.width||0,e.height||0,e.depth||0):t.set(0,0,0),t}set needsUpdate(t){t===!0&&this.version++}toJSON(t){let e=t===void 0||typeof t=="string";if(!e&&t.images[this.uuid]!==void 0)return t.images[this.uuid];let n={uuid:this.uuid,url:""},a=this.data;if(a!==null){let s;if(Array.isArray(a)){s=[];for(let r=0,o=a.length;r<o;r++)a[r].isDataTexture?s.push(Kl(a[r].image)):s.push(Kl(a[r]))}else s=Kl(a);n.url=s}return e||(t.images[this.uuid]=n),n}};Vg=0,Zl=new z,wn=class i extends Yn{constructor(t=i.DEFAULT_IMAGE,e=i.DEFAULT_MAPPING,n=si,a=si,s=mn,r=Ni,o=bn,c=an,l=i.DEFAULT_ANISOTROPY,h=Li){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:Vg++}),this.uuid=Ji(),this.name="",this.source=new $a(t),this.mipmaps=[],this.mapping=e,this.channel=0,this.wrapS=n,this.wrapT=a,this.magFilter=s,this.minFilter=r,this.anisotropy=l,this.format=o,this.internalFormat=null,this.type=c,this.offset=new Bt(0,0),this.repeat=new Bt(1,1),this.center=new Bt(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new Vt,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(t&&t.depth&&t.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(Zl).x}get height(){return this.source.getSize(Zl).y}get depth(){return this.source.getSize(Zl).z}get image(){return this.source.data}set image(t){this.source.data=t}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(t){return this.name=t.name,this.source=t.source,this.mipmaps=t.mipmaps.slice(0),this.mapping=t.mapping,this.channel=t.channel,this.wrapS=t.wrapS,this.wrapT=t.wrapT,this.magFilter=t.magFilter,this.minFilter=t.minFilter,this.anisotropy=t.anisotropy,this.format=t.format,this.internalFormat=t.internalFormat,this.type=t.type,this.normalized=t.normalized,this.offset.copy(t.offset),this.repeat.copy(t.repeat),this.center.copy(t.center),this.rotation=t.rotation,this.matrixAutoUpdate=t.matrixAutoUpdate,this.matrix.copy(t.matrix),this.generateMipmaps=t.generateMipmaps,this.mipmapsAutoUpdate=t.mipmapsAutoUpdate,this.premultiplyAlpha=t.premultiplyAlpha,this.flipY=t.flipY,this.unpackAlignment=t.unpackAlignment,this.colorSpace=t.colorSpace,this.renderTarget=t.renderTarget,this.isRenderTargetTexture=t.isRenderTargetTexture,this.isPMREMTexture=t.isPMREMTexture,this.isArrayTexture=t.isArrayTexture,this.userData=JSON.parse(JSON.stringify(t.userData)),this.needsUpdate=!0,this}setValues(t){for(let e in t){let n=t[e];if(n===void 0){Ft(`Texture.setValues(): parameter '${e}' has value of undefined.`);continue}let a=this[e];if(a===void 0){Ft(`Texture.setValues(): property '${e}' does not exist.`);continue}a&&n&&a.isVector2&&n.isVector2||a&&n&&a.isVector3&&n.isVector3||a&&n&&a.isMatrix3&&n.isMatrix3?a.copy(n):this[e]=n}}toJSON(t){let e=t===void 0||typeof t=="string";if(!e&&t.textures[this.uuid]!==void 0)return t.textures[this.uuid];let n={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(t).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(n.userData=this.userData),e||(t.textures[this.uuid]=n),n}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(t){if(this.mapping!==Hh)return t;if(t.applyMatrix3(this.matrix),t.x<0||t.x>1)switch(this.wrapS){case Go:t.x=t.x-Math.floor(t.x);break;case si:t.x=t.x<0?0:1;break;case Wo:Math.abs(Math.floor(t.x)%2)===1?t.x=Math.ceil(t.x)-t.x:t.x=t.x-Math.floor(t.x);break}if(t.y<0||t.y>1)switch(this.wrapT){case Go:t.y=t.y-Math.floor(t.y);break;case si:t.y=t.y<0?0:1;break;case Wo:Math.abs(Math.floor(t.y)%2)===1?t.y=Math.ceil(t.y)-t.y:t.y=t.y-Math.floor(t.y);break}return this.flipY&&(t.y=1-t.y),t}set needsUpdate(t){t===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(t){t===!0&&this.pmremVersion++}};wn.DEFAULT_IMAGE=null;wn.DEFAULT_MAPPING=Hh;wn.DEFAULT_ANISOTROPY=1;ld=class ld{constructor(t=0,e=0,n=0,a=1){this.x=t,this.y=e,this.z=n,this.w=a}get width(){return this.z}set width(t){this.z=t}get height(){return this.w}set height(t){this.w=t}set(t,e,n,a){return this.x=t,this.y=e,this.z=n,this.w=a,this}setScalar(t){return this.x=t,this.y=t,this.z=t,this.w=t,this}setX(t){return this.x=t,this}setY(t){return this.y=t,this}setZ(t){return this.z=t,this}setW(t){return this.w=t,this}setComponent(t,e){switch(t){case 0:this.x=e;break;case 1:this.y=e;break;case 2:this.z=e;break;case 3:this.w=e;break;default:throw new Error("THREE.Vector4: index is out of range: "+t)}return this}getComponent(t){switch(t){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+t)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(t){return this.x=t.x,this.y=t.y,this.z=t.z,this.w=t.w!==void 0?t.w:1,this}add(t){return this.x+=t.x,this.y+=t.y,this.z+=t.z,this.w+=t.w,this}addScalar(t){return this.x+=t,this.y+=t,this.z+=t,this.w+=t,this}addVectors(t,e){return this.x=t.x+e.x,this.y=t.y+e.y,this.z=t.z+e.z,this.w=t.w+e.w,this}addScaledVector(t,e){return this.x+=t.x*e,this.y+=t.y*e,this.z+=t.z*e,this.w+=t.w*e,this}sub(t){return this.x-=t.x,this.y-=t.y,this.z-=t.z,this.w-=t.w,this}subScalar(t){return this.x-=t,this.y-=t,this.z-=t,this.w-=t,this}subVectors(t,e){return this.x=t.x-e.x,this.y=t.y-e.y,this.z=t.z-e.z,this.w=t.w-e.w,this}multiply(t){return this.x*=t.x,this.y*=t.y,this.z*=t.z,this.w*=t.w,this}multiplyScalar(t){return this.x*=t,this.y*=t,this.z*=t,this.w*=t,this}applyMatrix4(t){let e=this.x,n=this.y,a=this.z,s=this.w,r=t.elements;return this.x=r[0]*e+r[4]*n+r[8]*a+r[12]*s,this.y=r[1]*e+r[5]*n+r[9]*a+r[13]*s,this.z=r[2]*e+r[6]*n+r[10]*a+r[14]*s,this.w=r[3]*e+r[7]*n+r[11]*a+r[15]*s,this}divide(t){return this.x/=t.x,this.y/=t.y,this.z/=t.z,this.w/=t.w,this}divideScalar(t){return this.multiplyScalar(1/t)}setAxisAngleFromQuaternion(t){this.w=2*Math.acos(t.w);let e=Math.sqrt(1-t.w*t.w);return e<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=t.x/e,this.y=t.y/e,this.z=t.z/e),this}setAxisAngleFromRotationMatrix(t){let e,n,a,s,c=t.elements,l=c[0],h=c[4],u=c[8],d=c[1],f=c[5],x=c[9],v=c[2],m=c[6],g=c[10];if(Math.abs(h-d)<.01&&Math.abs(u-v)<.01&&Math.abs(x-m)<.01){if(Math.abs(h+d)<.1&&Math.abs(u+v)<.1&&Math.abs(x+m)<.1&&Math.abs(l+f+g-3)<.1)return this.set(1,0,0,0),this;e=Math.PI;let w=(l+1)/2,p=(f+1)/2,_=(g+1)/2,S=(h+d)/4,b=(u+v)/4,M=(x+m)/4;return w>p&&w>_?w<.01?(n=0,a=.707106781,s=.707106781):(n=Math.sqrt(w),a=S/n,s=b/n):p>_?p<.01?(n=.707106781,a=0,s=.707106781):(a=Math.sqrt(p),n=S/a,s=M/a):_<.01?(n=.707106781,a=.707106781,s=0):(s=Math.sqrt(_),n=b/s,a=M/s),this.set(n,a,s,e),this}let y=Math.sqrt((m-x)*(m-x)+(u-v)*(u-v)+(d-h)*(d-h));return Math.abs(y)<.001&&(y=1),this.x=(m-x)/y,this.y=(u-v)/y,this.z=(d-h)/y,this.w=Math.acos((l+f+g-1)/2),this}setFromMatrixPosition(t){let e=t.elements;return this.x=e[12],this.y=e[13],this.z=e[14],this.w=e[15],this}min(t){return this.x=Math.min(this.x,t.x),this.y=Math.min(this.y,t.y),this.z=Math.min(this.z,t.z),this.w=Math.min(this.w,t.w),this}max(t){return this.x=Math.max(this.x,t.x),this.y=Math.max(this.y,t.y),this.z=Math.max(this.z,t.z),this.w=Math.max(this.w,t.w),this}clamp(t,e){return this.x=Wt(this.x,t.x,e.x),this.y=Wt(this.y,t.y,e.y),this.z=Wt(this.z,t.z,e.z),this.w=Wt(this.w,t.w,e.w),this}clampScalar(t,e){return this.x=Wt(this.x,t,e),this.y=Wt(this.y,t,e),this.z=Wt(this.z,t,e),this.w=Wt(this.w,t,e),this}clampLength(t,e){let n=this.length();return this.divideScalar(n||1).multiplyScalar(Wt(n,t,e))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(t){return this.x*t.x+this.y*t.y+this.z*t.z+this.w*t.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(t){return this.normalize().multiplyScalar(t)}lerp(t,e){return this.x+=(t.x-this.x)*e,this.y+=(t.y-this.y)*e,this.z+=(t.z-this.z)*e,this.w+=(t.w-this.w)*e,this}lerpVectors(t,e,n){return this.x=t.x+(e.x-t.x)*n,this.y=t.y+(e.y-t.y)*n,this.z=t.z+(e.z-t.z)*n,this.w=t.w+(e.w-t.w)*n,this}equals(t){return t.x===this.x&&t.y===this.y&&t.z===this.z&&t.w===this.w}fromArray(t,e=0){return this.x=t[e],this.y=t[e+1],this.z=t[e+2],this.w=t[e+3],this}toArray(t=[],e=0){return t[e]=this.x,t[e+1]=this.y,t[e+2]=this.z,t[e+3]=this.w,t}fromBufferAttribute(t,e){return this.x=t.getX(e),this.y=t.getY(e),this.z=t.getZ(e),this.w=t.getW(e),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}};ld.prototype.isVector4=!0;ce=ld,qo=class extends Yn{constructor(t=1,e=1,n={}){super(),n=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:mn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},n),this.isRenderTarget=!0,this.width=t,this.height=e,this.depth=n.depth,this.scissor=new ce(0,0,t,e),this.scissorTest=!1,this.viewport=new ce(0,0,t,e),this.textures=[];let a=n.count;for(let s=0;s<a;s++)this.textures[s]=new wn({width:t,height:e,depth:n.depth}),this.textures[s].isRenderTargetTexture=!0,this.textures[s].renderTarget=this;this._setTextureOptions(n),this.depthBuffer=n.depthBuffer,this.stencilBuffer=n.stencilBuffer,this.resolveColorBuffer=n.resolveColorBuffer,this.resolveDepthBuffer=n.resolveDepthBuffer,this.resolveStencilBuffer=n.resolveStencilBuffer,this.storeMultisampledColorBuffer=n.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=n.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=n.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=n.depthTexture,this.samples=n.samples,this.multiview=n.multiview,this.useArrayDepthTexture=n.useArrayDepthTexture}_setTextureOptions(t={}){let e={minFilter:mn,generateMipmaps:!1,flipY:!1,internalFormat:null};t.mapping!==void 0&&(e.mapping=t.mapping),t.wrapS!==void 0&&(e.wrapS=t.wrapS),t.wrapT!==void 0&&(e.wrapT=t.wrapT),t.wrapR!==void 0&&(e.wrapR=t.wrapR),t.magFilter!==void 0&&(e.magFilter=t.magFilter),t.minFilter!==void 0&&(e.minFilter=t.minFilter),t.format!==void 0&&(e.format=t.format),t.type!==void 0&&(e.type=t.type),t.anisotropy!==void 0&&(e.anisotropy=t.anisotropy),t.colorSpace!==void 0&&(e.colorSpace=t.colorSpace),t.flipY!==void 0&&(e.flipY=t.flipY),t.generateMipmaps!==void 0&&(e.generateMipmaps=t.generateMipmaps),t.mipmapsAutoUpdate!==void 0&&(e.mipmapsAutoUpdate=t.mipmapsAutoUpdate),t.internalFormat!==void 0&&(e.internalFormat=t.internalFormat);for(let n=0;n<this.textures.length;n++)this.textures[n].setValues(e)}get texture(){return this.textures[0]}set texture(t){this.textures[0]=t}set depthTexture(t){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),t!==null&&t.renderTarget===null&&(t.renderTarget=this),this._depthTexture=t}get depthTexture(){return this._depthTexture}setSize(t,e,n=1){if(this.width!==t||this.height!==e||this.depth!==n){this.width=t,this.height=e,this.depth=n;for(let a=0,s=this.textures.length;a<s;a++)this.textures[a].image.width=t,this.textures[a].image.height=e,this.textures[a].image.depth=n,this.textures[a].isData3DTexture!==!0&&(this.textures[a].isArrayTexture=this.textures[a].image.depth>1);this.dispose()}this.viewport.set(0,0,t,e),this.scissor.set(0,0,t,e)}clone(){return new this.constructor().copy(this)}copy(t){this.width=t.width,this.height=t.height,this.depth=t.depth,this.scissor.copy(t.scissor),this.scissorTest=t.scissorTest,this.viewport.copy(t.viewport),this.textures.length=0;for(let e=0,n=t.textures.length;e<n;e++){this.textures[e]=t.textures[e].clone(),this.textures[e].isRenderTargetTexture=!0,this.textures[e].renderTarget=this;let a=Object.assign({},t.textures[e].image);this.textures[e].source=new $a(a)}if(this.depthBuffer=t.depthBuffer,this.stencilBuffer=t.stencilBuffer,this.resolveColorBuffer=t.resolveColorBuffer,this.resolveDepthBuffer=t.resolveDepthBuffer,this.resolveStencilBuffer=t.resolveStencilBuffer,this.storeMultisampledColorBuffer=t.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=t.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=t.storeMultisampledStencilBuffer,t.depthTexture!==null)if(t.depthTexture.renderTarget===t){let e=t.depthTexture.clone();e.renderTarget=null,this.depthTexture=e}else this.depthTexture=t.depthTexture;else this.depthTexture=null;return this.samples=t.samples,this.multiview=t.multiview,this.useArrayDepthTexture=t.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}},Nn=class extends qo{constructor(t=1,e=1,n={}){super(t,e,n),this.isWebGLRenderTarget=!0}},tr=class extends wn{constructor(t=null,e=1,n=1,a=1){super(null),this.isDataArrayTexture=!0,this.image={data:t,width:e,height:n,depth:a},this.magFilter=De,this.minFilter=De,this.wrapR=si,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(t){return super.copy(t),this.wrapR=t.wrapR,this}addLayerUpdate(t){this.layerUpdates.add(t)}clearLayerUpdates(){this.layerUpdates.clear()}},Yo=class extends wn{constructor(t=null,e=1,n=1,a=1){super(null),this.isData3DTexture=!0,this.image={data:t,width:e,height:n,depth:a},this.magFilter=De,this.minFilter=De,this.wrapR=si,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(t){return super.copy(t),this.wrapR=t.wrapR,this}},pc=class pc{constructor(t,e,n,a,s,r,o,c,l,h,u,d,f,x,v,m){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],t!==void 0&&this.set(t,e,n,a,s,r,o,c,l,h,u,d,f,x,v,m)}set(t,e,n,a,s,r,o,c,l,h,u,d,f,x,v,m){let g=this.elements;return g[0]=t,g[4]=e,g[8]=n,g[12]=a,g[1]=s,g[5]=r,g[9]=o,g[13]=c,g[2]=l,g[6]=h,g[10]=u,g[14]=d,g[3]=f,g[7]=x,g[11]=v,g[15]=m,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new pc().fromArray(this.elements)}copy(t){let e=this.elements,n=t.elements;return e[0]=n[0],e[1]=n[1],e[2]=n[2],e[3]=n[3],e[4]=n[4],e[5]=n[5],e[6]=n[6],e[7]=n[7],e[8]=n[8],e[9]=n[9],e[10]=n[10],e[11]=n[11],e[12]=n[12],e[13]=n[13],e[14]=n[14],e[15]=n[15],this}copyPosition(t){let e=this.elements,n=t.elements;return e[12]=n[12],e[13]=n[13],e[14]=n[14],this}setFromMatrix3(t){let e=t.elements;return this.set(e[0],e[3],e[6],0,e[1],e[4],e[7],0,e[2],e[5],e[8],0,0,0,0,1),this}extractBasis(t,e,n){return this.determinantAffine()===0?(t.set(1,0,0),e.set(0,1,0),n.set(0,0,1),this):(t.setFromMatrixColumn(this,0),e.setFromMatrixColumn(this,1),n.setFromMatrixColumn(this,2),this)}makeBasis(t,e,n){return this.set(t.x,e.x,n.x,0,t.y,e.y,n.y,0,t.z,e.z,n.z,0,0,0,0,1),this}extractRotation(t){if(t.determinantAffine()===0)return this.identity();let e=this.elements,n=t.elements,a=1/Da.setFromMatrixColumn(t,0).length(),s=1/Da.setFromMatrixColumn(t,1).length(),r=1/Da.setFromMatrixColumn(t,2).length();return e[0]=n[0]*a,e[1]=n[1]*a,e[2]=n[2]*a,e[3]=0,e[4]=n[4]*s,e[5]=n[5]*s,e[6]=n[6]*s,e[7]=0,e[8]=n[8]*r,e[9]=n[9]*r,e[10]=n[10]*r,e[11]=0,e[12]=0,e[13]=0,e[14]=0,e[15]=1,this}makeRotationFromEuler(t){let e=this.elements,n=t.x,a=t.y,s=t.z,r=Math.cos(n),o=Math.sin(n),c=Math.cos(a),l=Math.sin(a),h=Math.cos(s),u=Math.sin(s);if(t.order==="XYZ"){let d=r*h,f=r*u,x=o*h,v=o*u;e[0]=c*h,e[4]=-c*u,e[8]=l,e[1]=f+x*l,e[5]=d-v*l,e[9]=-o*c,e[2]=v-d*l,e[6]=x+f*l,e[10]=r*c}else if(t.order==="YXZ"){let d=c*h,f=c*u,x=l*h,v=l*u;e[0]=d+v*o,e[4]=x*o-f,e[8]=r*l,e[1]=r*u,e[5]=r*h,e[9]=-o,e[2]=f*o-x,e[6]=v+d*o,e[10]=r*c}else if(t.order==="ZXY"){let d=c*h,f=c*u,x=l*h,v=l*u;e[0]=d-v*o,e[4]=-r*u,e[8]=x+f*o,e[1]=f+x*o,e[5]=r*h,e[9]=v-d*o,e[2]=-r*l,e[6]=o,e[10]=r*c}else if(t.order==="ZYX"){let d=r*h,f=r*u,x=o*h,v=o*u;e[0]=c*h,e[4]=x*l-f,e[8]=d*l+v,e[1]=c*u,e[5]=v*l+d,e[9]=f*l-x,e[2]=-l,e[6]=o*c,e[10]=r*c}else if(t.order==="YZX"){let d=r*c,f=r*l,x=o*c,v=o*l;e[0]=c*h,e[4]=v-d*u,e[8]=x*u+f,e[1]=u,e[5]=r*h,e[9]=-o*h,e[2]=-l*h,e[6]=f*u+x,e[10]=d-v*u}else if(t.order==="XZY"){let d=r*c,f=r*l,x=o*c,v=o*l;e[0]=c*h,e[4]=-u,e[8]=l*h,e[1]=d*u+v,e[5]=r*h,e[9]=f*u-x,e[2]=x*u-f,e[6]=o*h,e[10]=v*u+d}return e[3]=0,e[7]=0,e[11]=0,e[12]=0,e[13]=0,e[14]=0,e[15]=1,this}makeRotationFromQuaternion(t){return this.compose(Hg,t,Gg)}lookAt(t,e,n){let a=this.elements;return Tn.subVectors(t,e),Tn.lengthSq()===0&&(Tn.z=1),Tn.normalize(),Bi.crossVectors(n,Tn),Bi.lengthSq()===0&&(Math.abs(n.z)===1?Tn.x+=1e-4:Tn.z+=1e-4,Tn.normalize(),Bi.crossVectors(n,Tn)),Bi.normalize(),ro.crossVectors(Tn,Bi),a[0]=Bi.x,a[4]=ro.x,a[8]=Tn.x,a[1]=Bi.y,a[5]=ro.y,a[9]=Tn.y,a[2]=Bi.z,a[6]=ro.z,a[10]=Tn.z,this}multiply(t){return this.multiplyMatrices(this,t)}premultiply(t){return this.multiplyMatrices(t,this)}multiplyMatrices(t,e){let n=t.elements,a=e.elements,s=this.elements,r=n[0],o=n[4],c=n[8],l=n[12],h=n[1],u=n[5],d=n[9],f=n[13],x=n[2],v=n[6],m=n[10],g=n[14],y=n[3],w=n[7],p=n[11],_=n[15],S=a[0],b=a[4],M=a[8],E=a[12],A=a[1],I=a[5],N=a[9],L=a[13],P=a[2],U=a[6],V=a[10],O=a[14],Q=a[3],G=a[7],Z=a[11],et=a[15];return s[0]=r*S+o*A+c*P+l*Q,s[4]=r*b+o*I+c*U+l*G,s[8]=r*M+o*N+c*V+l*Z,s[12]=r*E+o*L+c*O+l*et,s[1]=h*S+u*A+d*P+f*Q,s[5]=h*b+u*I+d*U+f*G,s[9]=h*M+u*N+d*V+f*Z,s[13]=h*E+u*L+d*O+f*et,s[2]=x*S+v*A+m*P+g*Q,s[6]=x*b+v*I+m*U+g*G,s[10]=x*M+v*N+m*V+g*Z,s[14]=x*E+v*L+m*O+g*et,s[3]=y*S+w*A+p*P+_*Q,s[7]=y*b+w*I+p*U+_*G,s[11]=y*M+w*N+p*V+_*Z,s[15]=y*E+w*L+p*O+_*et,this}multiplyScalar(t){let e=this.elements;return e[0]*=t,e[4]*=t,e[8]*=t,e[12]*=t,e[1]*=t,e[5]*=t,e[9]*=t,e[13]*=t,e[2]*=t,e[6]*=t,e[10]*=t,e[14]*=t,e[3]*=t,e[7]*=t,e[11]*=t,e[15]*=t,this}determinant(){let t=this.elements,e=t[0],n=t[4],a=t[8],s=t[12],r=t[1],o=t[5],c=t[9],l=t[13],h=t[2],u=t[6],d=t[10],f=t[14],x=t[3],v=t[7],m=t[11],g=t[15],y=c*f-l*d,w=o*f-l*u,p=o*d-c*u,_=r*f-l*h,S=r*d-c*h,b=r*u-o*h;return e*(v*y-m*w+g*p)-n*(x*y-m*_+g*S)+a*(x*w-v*_+g*b)-s*(x*p-v*S+m*b)}determinantAffine(){let t=this.elements,e=t[0],n=t[4],a=t[8],s=t[1],r=t[5],o=t[9],c=t[2],l=t[6],h=t[10];return e*(r*h-o*l)-n*(s*h-o*c)+a*(s*l-r*c)}transpose(){let t=this.elements,e;return e=t[1],t[1]=t[4],t[4]=e,e=t[2],t[2]=t[8],t[8]=e,e=t[6],t[6]=t[9],t[9]=e,e=t[3],t[3]=t[12],t[12]=e,e=t[7],t[7]=t[13],t[13]=e,e=t[11],t[11]=t[14],t[14]=e,this}setPosition(t,e,n){let a=this.elements;return t.isVector3?(a[12]=t.x,a[13]=t.y,a[14]=t.z):(a[12]=t,a[13]=e,a[14]=n),this}invert(){let t=this.elements,e=t[0],n=t[1],a=t[2],s=t[3],r=t[4],o=t[5],c=t[6],l=t[7],h=t[8],u=t[9],d=t[10],f=t[11],x=t[12],v=t[13],m=t[14],g=t[15],y=e*o-n*r,w=e*c-a*r,p=e*l-s*r,_=n*c-a*o,S=n*l-s*o,b=a*l-s*c,M=h*v-u*x,E=h*m-d*x,A=h*g-f*x,I=u*m-d*v,N=u*g-f*v,L=d*g-f*m,P=y*L-w*N+p*I+_*A-S*E+b*M;if(P===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);let U=1/P;return t[0]=(o*L-c*N+l*I)*U,t[1]=(a*N-n*L-s*I)*U,t[2]=(v*b-m*S+g*_)*U,t[3]=(d*S-u*b-f*_)*U,t[4]=(c*A-r*L-l*E)*U,t[5]=(e*L-a*A+s*E)*U,t[6]=(m*p-x*b-g*w)*U,t[7]=(h*b-d*p+f*w)*U,t[8]=(r*N-o*A+l*M)*U,t[9]=(n*A-e*N-s*M)*U,t[10]=(x*S-v*p+g*y)*U,t[11]=(u*p-h*S-f*y)*U,t[12]=(o*E-r*I-c*M)*U,t[13]=(e*I-n*E+a*M)*U,t[14]=(v*w-x*_-m*y)*U,t[15]=(h*_-u*w+d*y)*U,this}scale(t){let e=this.elements,n=t.x,a=t.y,s=t.z;return e[0]*=n,e[4]*=a,e[8]*=s,e[1]*=n,e[5]*=a,e[9]*=s,e[2]*=n,e[6]*=a,e[10]*=s,e[3]*=n,e[7]*=a,e[11]*=s,this}getMaxScaleOnAxis(){let t=this.elements,e=t[0]*t[0]+t[1]*t[1]+t[2]*t[2],n=t[4]*t[4]+t[5]*t[5]+t[6]*t[6],a=t[8]*t[8]+t[9]*t[9]+t[10]*t[10];return Math.sqrt(Math.max(e,n,a))}makeTranslation(t,e,n){return t.isVector3?this.set(1,0,0,t.x,0,1,0,t.y,0,0,1,t.z,0,0,0,1):this.set(1,0,0,t,0,1,0,e,0,0,1,n,0,0,0,1),this}makeRotationX(t){let e=Math.cos(t),n=Math.sin(t);return this.set(1,0,0,0,0,e,-n,0,0,n,e,0,0,0,0,1),this}makeRotationY(t){let e=Math.cos(t),n=Math.sin(t);return this.set(e,0,n,0,0,1,0,0,-n,0,e,0,0,0,0,1),this}makeRotationZ(t){let e=Math.cos(t),n=Math.sin(t);return this.set(e,-n,0,0,n,e,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(t,e){let n=Math.cos(e),a=Math.sin(e),s=1-n,r=t.x,o=t.y,c=t.z,l=s*r,h=s*o;return this.set(l*r+n,l*o-a*c,l*c+a*o,0,l*o+a*c,h*o+n,h*c-a*r,0,l*c-a*o,h*c+a*r,s*c*c+n,0,0,0,0,1),this}makeScale(t,e,n){return this.set(t,0,0,0,0,e,0,0,0,0,n,0,0,0,0,1),this}makeShear(t,e,n,a,s,r){return this.set(1,n,s,0,t,1,r,0,e,a,1,0,0,0,0,1),this}compose(t,e,n){let a=this.elements,s=e._x,r=e._y,o=e._z,c=e._w,l=s+s,h=r+r,u=o+o,d=s*l,f=s*h,x=s*u,v=r*h,m=r*u,g=o*u,y=c*l,w=c*h,p=c*u,_=n.x,S=n.y,b=n.z;return a[0]=(1-(v+g))*_,a[1]=(f+p)*_,a[2]=(x-w)*_,a[3]=0,a[4]=(f-p)*S,a[5]=(1-(d+g))*S,a[6]=(m+y)*S,a[7]=0,a[8]=(x+w)*b,a[9]=(m-y)*b,a[10]=(1-(d+v))*b,a[11]=0,a[12]=t.x,a[13]=t.y,a[14]=t.z,a[15]=1,this}decompose(t,e,n){let a=this.elements;t.x=a[12],t.y=a[13],t.z=a[14];let s=this.determinantAffine();if(s===0)return n.set(1,1,1),e.identity(),this;let r=Da.set(a[0],a[1],a[2]).length(),o=Da.set(a[4],a[5],a[6]).length(),c=Da.set(a[8],a[9],a[10]).length();s<0&&(r=-r),jn.copy(this);let l=1/r,h=1/o,u=1/c;return jn.elements[0]*=l,jn.elements[1]*=l,jn.elements[2]*=l,jn.elements[4]*=h,jn.elements[5]*=h,jn.elements[6]*=h,jn.elements[8]*=u,jn.elements[9]*=u,jn.elements[10]*=u,e.setFromRotationMatrix(jn),n.x=r,n.y=o,n.z=c,this}makePerspective(t,e,n,a,s,r,o=Fn,c=!1){let l=this.elements,h=2*s/(e-t),u=2*s/(n-a),d=(e+t)/(e-t),f=(n+a)/(n-a),x,v;if(c)x=s/(r-s),v=r*s/(r-s);else if(o===Fn)x=-(r+s)/(r-s),v=-2*r*s/(r-s);else if(o===Ka)x=-r/(r-s),v=-r*s/(r-s);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+o);return l[0]=h,l[4]=0,l[8]=d,l[12]=0,l[1]=0,l[5]=u,l[9]=f,l[13]=0,l[2]=0,l[6]=0,l[10]=x,l[14]=v,l[3]=0,l[7]=0,l[11]=-1,l[15]=0,this}makeOrthographic(t,e,n,a,s,r,o=Fn,c=!1){let l=this.elements,h=2/(e-t),u=2/(n-a),d=-(e+t)/(e-t),f=-(n+a)/(n-a),x,v;if(c)x=1/(r-s),v=r/(r-s);else if(o===Fn)x=-2/(r-s),v=-(r+s)/(r-s);else if(o===Ka)x=-1/(r-s),v=-s/(r-s);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+o);return l[0]=h,l[4]=0,l[8]=0,l[12]=d,l[1]=0,l[5]=u,l[9]=0,l[13]=f,l[2]=0,l[6]=0,l[10]=x,l[14]=v,l[3]=0,l[7]=0,l[11]=0,l[15]=1,this}equals(t){let e=this.elements,n=t.elements;for(let a=0;a<16;a++)if(e[a]!==n[a])return!1;return!0}fromArray(t,e=0){for(let n=0;n<16;n++)this.elements[n]=t[n+e];return this}toArray(t=[],e=0){let n=this.elements;return t[e]=n[0],t[e+1]=n[1],t[e+2]=n[2],t[e+3]=n[3],t[e+4]=n[4],t[e+5]=n[5],t[e+6]=n[6],t[e+7]=n[7],t[e+8]=n[8],t[e+9]=n[9],t[e+10]=n[10],t[e+11]=n[11],t[e+12]=n[12],t[e+13]=n[13],t[e+14]=n[14],t[e+15]=n[15],t}};pc.prototype.isMatrix4=!0;oe=pc,Da=new z,jn=new oe,Hg=new z(0,0,0),Gg=new z(1,1,1),Bi=new z,ro=new z,Tn=new z,wu=new oe,Au=new Cn,Ii=class i{constructor(t=0,e=0,n=0,a=i.DEFAULT_ORDER){this.isEuler=!0,this._x=t,this._y=e,this._z=n,this._order=a}get x(){return this._x}set x(t){this._x=t,this._onChangeCallback()}get y(){return this._y}set y(t){this._y=t,this._onChangeCallback()}get z(){return this._z}set z(t){this._z=t,this._onChangeCallback()}get order(){return this._order}set order(t){this._order=t,this._onChangeCallback()}set(t,e,n,a=this._order){return this._x=t,this._y=e,this._z=n,this._order=a,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(t){return this._x=t._x,this._y=t._y,this._z=t._z,this._order=t._order,this._onChangeCallback(),this}setFromRotationMatrix(t,e=this._order,n=!0){let a=t.elements,s=a[0],r=a[4],o=a[8],c=a[1],l=a[5],h=a[9],u=a[2],d=a[6],f=a[10];switch(e){case"XYZ":this._y=Math.asin(Wt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(-h,f),this._z=Math.atan2(-r,s)):(this._x=Math.atan2(d,l),this._z=0);break;case"YXZ":this._x=Math.asin(-Wt(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(o,f),this._z=Math.atan2(c,l)):(this._y=Math.atan2(-u,s),this._z=0);break;case"ZXY":this._x=Math.asin(Wt(d,-1,1)),Math.abs(d)<.9999999?(this._y=Math.atan2(-u,f),this._z=Math.atan2(-r,l)):(this._y=0,this._z=Math.atan2(c,s));break;case"ZYX":this._y=Math.asin(-Wt(u,-1,1)),Math.abs(u)<.9999999?(this._x=Math.atan2(d,f),this._z=Math.atan2(c,s)):(this._x=0,this._z=Math.atan2(-r,l));break;case"YZX":this._z=Math.asin(Wt(c,-1,1)),Math.abs(c)<.9999999?(this._x=Math.atan2(-h,l),this._y=Math.atan2(-u,s)):(this._x=0,this._y=Math.atan2(o,f));break;case"XZY":this._z=Math.asin(-Wt(r,-1,1)),Math.abs(r)<.9999999?(this._x=Math.atan2(d,l),this._y=Math.atan2(o,s)):(this._x=Math.atan2(-h,f),this._y=0);break;default:Ft("Euler: .setFromRotationMatrix() encountered an unknown order: "+e)}return this._order=e,n===!0&&this._onChangeCallback(),this}setFromQuaternion(t,e,n){return wu.makeRotationFromQuaternion(t),this.setFromRotationMatrix(wu,e,n)}setFromVector3(t,e=this._order){return this.set(t.x,t.y,t.z,e)}reorder(t){return Au.setFromEuler(this),this.setFromQuaternion(Au,t)}equals(t){return t._x===this._x&&t._y===this._y&&t._z===this._z&&t._order===this._order}fromArray(t){return this._x=t[0],this._y=t[1],this._z=t[2],t[3]!==void 0&&(this._order=t[3]),this._onChangeCallback(),this}toArray(t=[],e=0){return t[e]=this._x,t[e+1]=this._y,t[e+2]=this._z,t[e+3]=this._order,t}_onChange(t){return this._onChangeCallback=t,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}};Ii.DEFAULT_ORDER="XYZ";ts=class{constructor(){this.mask=1}set(t){this.mask=(1<<t|0)>>>0}enable(t){this.mask|=1<<t|0}enableAll(){this.mask=-1}toggle(t){this.mask^=1<<t|0}disable(t){this.mask&=~(1<<t|0)}disableAll(){this.mask=0}test(t){return(this.mask&t.mask)!==0}isEnabled(t){return(this.mask&(1<<t|0))!==0}},Wg=0,Eu=new z,Ua=new Cn,yi=new oe,oo=new z,Vs=new z,jg=new z,Xg=new Cn,Tu=new z(1,0,0),Iu=new z(0,1,0),Ru=new z(0,0,1),Cu={type:"added"},qg={type:"removed"},Oa={type:"childadded",child:null},Ql={type:"childremoved",child:null},Fe=class i extends Yn{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:Wg++}),this.uuid=Ji(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=i.DEFAULT_UP.clone();let t=new z,e=new Ii,n=new Cn,a=new z(1,1,1);function s(){n.setFromEuler(e,!1)}function r(){e.setFromQuaternion(n,void 0,!1)}e._onChange(s),n._onChange(r),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:t},rotation:{configurable:!0,enumerable:!0,value:e},quaternion:{configurable:!0,enumerable:!0,value:n},scale:{configurable:!0,enumerable:!0,value:a},modelViewMatrix:{value:new oe},normalMatrix:{value:new Vt}}),this.matrix=new oe,this.matrixWorld=new oe,this.matrixAutoUpdate=i.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=i.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new ts,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(t){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(t),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(t){return this.quaternion.premultiply(t),this}setRotationFromAxisAngle(t,e){this.quaternion.setFromAxisAngle(t,e)}setRotationFromEuler(t){this.quaternion.setFromEuler(t,!0)}setRotationFromMatrix(t){this.quaternion.setFromRotationMatrix(t)}setRotationFromQuaternion(t){this.quaternion.copy(t)}rotateOnAxis(t,e){return Ua.setFromAxisAngle(t,e),this.quaternion.multiply(Ua),this}rotateOnWorldAxis(t,e){return Ua.setFromAxisAngle(t,e),this.quaternion.premultiply(Ua),this}rotateX(t){return this.rotateOnAxis(Tu,t)}rotateY(t){return this.rotateOnAxis(Iu,t)}rotateZ(t){return this.rotateOnAxis(Ru,t)}translateOnAxis(t,e){return Eu.copy(t).applyQuaternion(this.quaternion),this.position.add(Eu.multiplyScalar(e)),this}translateX(t){return this.translateOnAxis(Tu,t)}translateY(t){return this.translateOnAxis(Iu,t)}translateZ(t){return this.translateOnAxis(Ru,t)}localToWorld(t){return this.updateWorldMatrix(!0,!1),t.applyMatrix4(this.matrixWorld)}worldToLocal(t){return this.updateWorldMatrix(!0,!1),t.applyMatrix4(yi.copy(this.matrixWorld).invert())}lookAt(t,e,n){t.isVector3?oo.copy(t):oo.set(t,e,n);let a=this.parent;this.updateWorldMatrix(!0,!1),Vs.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?yi.lookAt(Vs,oo,this.up):yi.lookAt(oo,Vs,this.up),this.quaternion.setFromRotationMatrix(yi),a&&(yi.extractRotation(a.matrixWorld),Ua.setFromRotationMatrix(yi),this.quaternion.premultiply(Ua.invert()))}add(t){if(arguments.length>1){for(let e=0;e<arguments.length;e++)this.add(arguments[e]);return this}return t===this?(zt("Object3D.add: object can't be added as a child of itself.",t),this):(t&&t.isObject3D?(t.removeFromParent(),t.parent=this,this.children.push(t),t.dispatchEvent(Cu),Oa.child=t,this.dispatchEvent(Oa),Oa.child=null):zt("Object3D.add: object not an instance of THREE.Object3D.",t),this)}remove(t){if(arguments.length>1){for(let n=0;n<arguments.length;n++)this.remove(arguments[n]);return this}let e=this.children.indexOf(t);return e!==-1&&(t.parent=null,this.children.splice(e,1),t.dispatchEvent(qg),Ql.child=t,this.dispatchEvent(Ql),Ql.child=null),this}removeFromParent(){let t=this.parent;return t!==null&&t.remove(this),this}clear(){return this.remove(...this.children)}attach(t){return this.updateWorldMatrix(!0,!1),yi.copy(this.matrixWorld).invert(),t.parent!==null&&(t.parent.updateWorldMatrix(!0,!1),yi.multiply(t.parent.matrixWorld)),t.applyMatrix4(yi),t.removeFromParent(),t.parent=this,this.children.push(t),t.updateWorldMatrix(!1,!0),t.dispatchEvent(Cu),Oa.child=t,this.dispatchEvent(Oa),Oa.child=null,this}getObjectById(t){return this.getObjectByProperty("id",t)}getObjectByName(t){return this.getObjectByProperty("name",t)}getObjectByProperty(t,e){if(this[t]===e)return this;for(let n=0,a=this.children.length;n<a;n++){let r=this.children[n].getObjectByProperty(t,e);if(r!==void 0)return r}}getObjectsByProperty(t,e,n=[]){this[t]===e&&n.push(this);let a=this.children;for(let s=0,r=a.length;s<r;s++)a[s].getObjectsByProperty(t,e,n);return n}getWorldPosition(t){return this.updateWorldMatrix(!0,!1),t.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(t){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(Vs,t,jg),t}getWorldScale(t){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(Vs,Xg,t),t}getWorldDirection(t){this.updateWorldMatrix(!0,!1);let e=this.matrixWorld.elements;return t.set(e[8],e[9],e[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(t){t(this);let e=this.children;for(let n=0,a=e.length;n<a;n++)e[n].traverse(t)}traverseVisible(t){if(this.visible===!1)return;t(this);let e=this.children;for(let n=0,a=e.length;n<a;n++)e[n].traverseVisible(t)}traverseAncestors(t){let e=this.parent;e!==null&&(t(e),e.traverseAncestors(t))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);let t=this.pivot;if(t!==null){let e=t.x,n=t.y,a=t.z,s=this.matrix.elements;s[12]+=e-s[0]*e-s[4]*n-s[8]*a,s[13]+=n-s[1]*e-s[5]*n-s[9]*a,s[14]+=a-s[2]*e-s[6]*n-s[10]*a}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(t){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||t)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,t=!0);let e=this.children;for(let n=0,a=e.length;n<a;n++)e[n].updateMatrixWorld(t)}updateWorldMatrix(t,e,n=!1){let a=this.parent;if(t===!0&&a!==null&&a.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||n)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,n=!0),e===!0){let s=this.children;for(let r=0,o=s.length;r<o;r++)s[r].updateWorldMatrix(!1,!0,n)}}toJSON(t){let e=t===void 0||typeof t=="string",n={};e&&(t={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},n.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});let a={};a.uuid=this.uuid,a.type=this.type,a.name=this.name,a.castShadow=this.castShadow,a.receiveShadow=this.receiveShadow,a.visible=this.visible,a.frustumCulled=this.frustumCulled,a.renderOrder=this.renderOrder,a.static=this.static,a.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(a.userData=this.userData),a.layers=this.layers.mask,a.matrix=this.matrix.toArray(),a.up=this.up.toArray(),this.pivot!==null&&(a.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(a.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(a.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(a.type="InstancedMesh",a.count=this.count,a.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(a.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(a.type="BatchedMesh",a.perObjectFrustumCulled=this.perObjectFrustumCulled,a.sortObjects=this.sortObjects,a.drawRanges=this._drawRanges,a.reservedRanges=this._reservedRanges,a.geometryInfo=this._geometryInfo.map(o=>({...o,boundingBox:o.boundingBox?o.boundingBox.toJSON():void 0,boundingSphere:o.boundingSphere?o.boundingSphere.toJSON():void 0})),a.instanceInfo=this._instanceInfo.map(o=>({...o})),a.availableInstanceIds=this._availableInstanceIds.slice(),a.availableGeometryIds=this._availableGeometryIds.slice(),a.nextIndexStart=this._nextIndexStart,a.nextVertexStart=this._nextVertexStart,a.geometryCount=this._geometryCount,a.maxInstanceCount=this._maxInstanceCount,a.maxVertexCount=this._maxVertexCount,a.maxIndexCount=this._maxIndexCount,a.geometryInitialized=this._geometryInitialized,a.matricesTexture=this._matricesTexture.toJSON(t),a.indirectTexture=this._indirectTexture.toJSON(t),this._colorsTexture!==null&&(a.colorsTexture=this._colorsTexture.toJSON(t)),this.boundingSphere!==null&&(a.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(a.boundingBox=this.boundingBox.toJSON()));function s(o,c){return o[c.uuid]===void 0&&(o[c.uuid]=c.toJSON(t)),c.uuid}if(this.isScene)this.background&&(this.background.isColor?a.background=this.background.toJSON():this.background.isTexture&&(a.background=this.background.toJSON(t).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(a.environment=this.environment.toJSON(t).uuid);else if(this.isMesh||this.isLine||this.isPoints){a.geometry=s(t.geometries,this.geometry);let o=this.geometry.parameters;if(o!==void 0&&o.shapes!==void 0){let c=o.shapes;if(Array.isArray(c))for(let l=0,h=c.length;l<h;l++){let u=c[l];s(t.shapes,u)}else s(t.shapes,c)}}if(this.isSkinnedMesh&&(a.bindMode=this.bindMode,a.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(s(t.skeletons,this.skeleton),a.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){let o=[];for(let c=0,l=this.material.length;c<l;c++)o.push(s(t.materials,this.material[c]));a.material=o}else a.material=s(t.materials,this.material);if(this.children.length>0){a.children=[];for(let o=0;o<this.children.length;o++)a.children.push(this.children[o].toJSON(t).object)}if(this.animations.length>0){a.animations=[];for(let o=0;o<this.animations.length;o++){let c=this.animations[o];a.animations.push(s(t.animations,c))}}if(e){let o=r(t.geometries),c=r(t.materials),l=r(t.textures),h=r(t.images),u=r(t.shapes),d=r(t.skeletons),f=r(t.animations),x=r(t.nodes);o.length>0&&(n.geometries=o),c.length>0&&(n.materials=c),l.length>0&&(n.textures=l),h.length>0&&(n.images=h),u.length>0&&(n.shapes=u),d.length>0&&(n.skeletons=d),f.length>0&&(n.animations=f),x.length>0&&(n.nodes=x)}return n.object=a,n;function r(o){let c=[];for(let l in o){let h=o[l];delete h.metadata,c.push(h)}return c}}clone(t){return new this.constructor().copy(this,t)}copy(t,e=!0){if(this.name=t.name,this.up.copy(t.up),this.position.copy(t.position),this.rotation.order=t.rotation.order,this.quaternion.copy(t.quaternion),this.scale.copy(t.scale),this.pivot=t.pivot!==null?t.pivot.clone():null,this.matrix.copy(t.matrix),this.matrixWorld.copy(t.matrixWorld),this.matrixAutoUpdate=t.matrixAutoUpdate,this.matrixWorldAutoUpdate=t.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=t.matrixWorldNeedsUpdate,this.layers.mask=t.layers.mask,this.visible=t.visible,this.castShadow=t.castShadow,this.receiveShadow=t.receiveShadow,this.frustumCulled=t.frustumCulled,this.renderOrder=t.renderOrder,this.static=t.static,this.animations=t.animations.slice(),this.userData=JSON.parse(JSON.stringify(t.userData)),e===!0)for(let n=0;n<t.children.length;n++){let a=t.children[n];this.add(a.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}};Fe.DEFAULT_UP=new z(0,1,0);Fe.DEFAULT_MATRIX_AUTO_UPDATE=!0;Fe.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;wi=class extends Fe{constructor(){super(),this.isGroup=!0,this.type="Group"}},Yg={type:"move"},es=class{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new wi,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new wi,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new z,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new z),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new wi,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new z,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new z,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(t){return this._targetRay!==null&&this._targetRay.dispatchEvent(t),this._grip!==null&&this._grip.dispatchEvent(t),this._hand!==null&&this._hand.dispatchEvent(t),this}connect(t){if(t&&t.hand){let e=this._hand;if(e)for(let n of t.hand.values())this._getHandJoint(e,n)}return this.dispatchEvent({type:"connected",data:t}),this}disconnect(t){return this.dispatchEvent({type:"disconnected",data:t}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(t,e,n){let a=null,s=null,r=null,o=this._targetRay,c=this._grip,l=this._hand;if(t&&e.session.visibilityState!=="visible-blurred"){if(l&&t.hand){r=!0;for(let v of t.hand.values()){let m=e.getJointPose(v,n),g=this._getHandJoint(l,v);m!==null&&(g.matrix.fromArray(m.transform.matrix),g.matrix.decompose(g.position,g.quaternion,g.scale),g.matrixWorldNeedsUpdate=!0,g.jointRadius=m.radius),g.visible=m!==null}let h=l.joints["index-finger-tip"],u=l.joints["thumb-tip"],d=h.position.distanceTo(u.position),f=.02,x=.005;l.inputState.pinching&&d>f+x?(l.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:t.handedness,target:this})):!l.inputState.pinching&&d<=f-x&&(l.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:t.handedness,target:this}))}else c!==null&&t.gripSpace&&(s=e.getPose(t.gripSpace,n),s!==null&&(c.matrix.fromArray(s.transform.matrix),c.matrix.decompose(c.position,c.quaternion,c.scale),c.matrixWorldNeedsUpdate=!0,s.linearVelocity?(c.hasLinearVelocity=!0,c.linearVelocity.copy(s.linearVelocity)):c.hasLinearVelocity=!1,s.angularVelocity?(c.hasAngularVelocity=!0,c.angularVelocity.copy(s.angularVelocity)):c.hasAngularVelocity=!1,c.eventsEnabled&&c.dispatchEvent({type:"gripUpdated",data:t,target:this})));o!==null&&(a=e.getPose(t.targetRaySpace,n),a===null&&s!==null&&(a=s),a!==null&&(o.matrix.fromArray(a.transform.matrix),o.matrix.decompose(o.position,o.quaternion,o.scale),o.matrixWorldNeedsUpdate=!0,a.linearVelocity?(o.hasLinearVelocity=!0,o.linearVelocity.copy(a.linearVelocity)):o.hasLinearVelocity=!1,a.angularVelocity?(o.hasAngularVelocity=!0,o.angularVelocity.copy(a.angularVelocity)):o.hasAngularVelocity=!1,this.dispatchEvent(Yg)))}return o!==null&&(o.visible=a!==null),c!==null&&(c.visible=s!==null),l!==null&&(l.visible=r!==null),this}_getHandJoint(t,e){if(t.joints[e.jointName]===void 0){let n=new wi;n.matrixAutoUpdate=!1,n.visible=!1,t.joints[e.jointName]=n,t.add(n)}return t.joints[e.jointName]}},kf={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},ki={h:0,s:0,l:0},co={h:0,s:0,l:0};jt=class{constructor(t,e,n){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(t,e,n)}set(t,e,n){if(e===void 0&&n===void 0){let a=t;a&&a.isColor?this.copy(a):typeof a=="number"?this.setHex(a):typeof a=="string"&&this.setStyle(a)}else this.setRGB(t,e,n);return this}setScalar(t){return this.r=t,this.g=t,this.b=t,this}setHex(t,e=Rn){return t=Math.floor(t),this.r=(t>>16&255)/255,this.g=(t>>8&255)/255,this.b=(t&255)/255,Kt.colorSpaceToWorking(this,e),this}setRGB(t,e,n,a=Kt.workingColorSpace){return this.r=t,this.g=e,this.b=n,Kt.colorSpaceToWorking(this,a),this}setHSL(t,e,n,a=Kt.workingColorSpace){if(t=Qh(t,1),e=Wt(e,0,1),n=Wt(n,0,1),e===0)this.r=this.g=this.b=n;else{let s=n<=.5?n*(1+e):n+e-n*e,r=2*n-s;this.r=$l(r,s,t+1/3),this.g=$l(r,s,t),this.b=$l(r,s,t-1/3)}return Kt.colorSpaceToWorking(this,a),this}setStyle(t,e=Rn){function n(s){s!==void 0&&parseFloat(s)<1&&Ft("Color: Alpha component of "+t+" will be ignored.")}let a;if(a=/^(\w+)\(([^\)]*)\)/.exec(t)){let s,r=a[1],o=a[2];switch(r){case"rgb":case"rgba":if(s=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(s[4]),this.setRGB(Math.min(255,parseInt(s[1],10))/255,Math.min(255,parseInt(s[2],10))/255,Math.min(255,parseInt(s[3],10))/255,e);if(s=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(s[4]),this.setRGB(Math.min(100,parseFloat(s[1]))/100,Math.min(100,parseFloat(s[2]))/100,Math.min(100,parseFloat(s[3]))/100,e);break;case"hsl":case"hsla":if(s=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(o))return n(s[4]),this.setHSL(parseFloat(s[1])/360,parseFloat(s[2])/100,parseFloat(s[3])/100,e);break;default:Ft("Color: Unknown color model "+t)}}else if(a=/^\#([A-Fa-f\d]+)$/.exec(t)){let s=a[1],r=s.length;if(r===3)return this.setRGB(parseInt(s.charAt(0),16)/15,parseInt(s.charAt(1),16)/15,parseInt(s.charAt(2),16)/15,e);if(r===6)return this.setHex(parseInt(s,16),e);Ft("Color: Invalid hex color "+t)}else if(t&&t.length>0)return this.setColorName(t,e);return this}setColorName(t,e=Rn){let n=kf[t.toLowerCase()];return n!==void 0?this.setHex(n,e):Ft("Color: Unknown color "+t),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(t){return this.r=t.r,this.g=t.g,this.b=t.b,this}copySRGBToLinear(t){return this.r=Ai(t.r),this.g=Ai(t.g),this.b=Ai(t.b),this}copyLinearToSRGB(t){return this.r=Ya(t.r),this.g=Ya(t.g),this.b=Ya(t.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(t=Rn){return Kt.workingToColorSpace(tn.copy(this),t),Math.round(Wt(tn.r*255,0,255))*65536+Math.round(Wt(tn.g*255,0,255))*256+Math.round(Wt(tn.b*255,0,255))}getHexString(t=Rn){return("000000"+this.getHex(t).toString(16)).slice(-6)}getHSL(t,e=Kt.workingColorSpace){Kt.workingToColorSpace(tn.copy(this),e);let n=tn.r,a=tn.g,s=tn.b,r=Math.max(n,a,s),o=Math.min(n,a,s),c,l,h=(o+r)/2;if(o===r)c=0,l=0;else{let u=r-o;switch(l=h<=.5?u/(r+o):u/(2-r-o),r){case n:c=(a-s)/u+(a<s?6:0);break;case a:c=(s-n)/u+2;break;case s:c=(n-a)/u+4;break}c/=6}return t.h=c,t.s=l,t.l=h,t}getRGB(t,e=Kt.workingColorSpace){return Kt.workingToColorSpace(tn.copy(this),e),t.r=tn.r,t.g=tn.g,t.b=tn.b,t}getStyle(t=Rn){Kt.workingToColorSpace(tn.copy(this),t);let e=tn.r,n=tn.g,a=tn.b;return t!==Rn?`color(${t} ${e.toFixed(3)} ${n.toFixed(3)} ${a.toFixed(3)})`:`rgb(${Math.round(e*255)},${Math.round(n*255)},${Math.round(a*255)})`}offsetHSL(t,e,n){return this.getHSL(ki),this.setHSL(ki.h+t,ki.s+e,ki.l+n)}add(t){return this.r+=t.r,this.g+=t.g,this.b+=t.b,this}addColors(t,e){return this.r=t.r+e.r,this.g=t.g+e.g,this.b=t.b+e.b,this}addScalar(t){return this.r+=t,this.g+=t,this.b+=t,this}sub(t){return this.r=Math.max(0,this.r-t.r),this.g=Math.max(0,this.g-t.g),this.b=Math.max(0,this.b-t.b),this}multiply(t){return this.r*=t.r,this.g*=t.g,this.b*=t.b,this}multiplyScalar(t){return this.r*=t,this.g*=t,this.b*=t,this}lerp(t,e){return this.r+=(t.r-this.r)*e,this.g+=(t.g-this.g)*e,this.b+=(t.b-this.b)*e,this}lerpColors(t,e,n){return this.r=t.r+(e.r-t.r)*n,this.g=t.g+(e.g-t.g)*n,this.b=t.b+(e.b-t.b)*n,this}lerpHSL(t,e){this.getHSL(ki),t.getHSL(co);let n=Ys(ki.h,co.h,e),a=Ys(ki.s,co.s,e),s=Ys(ki.l,co.l,e);return this.setHSL(n,a,s),this}setFromVector3(t){return this.r=t.x,this.g=t.y,this.b=t.z,this}applyMatrix3(t){let e=this.r,n=this.g,a=this.b,s=t.elements;return this.r=s[0]*e+s[3]*n+s[6]*a,this.g=s[1]*e+s[4]*n+s[7]*a,this.b=s[2]*e+s[5]*n+s[8]*a,this}equals(t){return t.r===this.r&&t.g===this.g&&t.b===this.b}fromArray(t,e=0){return this.r=t[e],this.g=t[e+1],this.b=t[e+2],this}toArray(t=[],e=0){return t[e]=this.r,t[e+1]=this.g,t[e+2]=this.b,t}fromBufferAttribute(t,e){return this.r=t.getX(e),this.g=t.getY(e),this.b=t.getZ(e),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}},tn=new jt;jt.NAMES=kf;er=class extends Fe{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new Ii,this.environmentIntensity=1,this.environmentRotation=new Ii,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(t,e){return super.copy(t,e),this.background=t.background!==null?t.background.clone():null,this.environment=t.environment!==null?t.environment.clone():null,this.fog=t.fog!==null?t.fog.clone():null,this.backgroundBlurriness=t.backgroundBlurriness,this.backgroundIntensity=t.backgroundIntensity,this.backgroundRotation.copy(t.backgroundRotation),this.environmentIntensity=t.environmentIntensity,this.environmentRotation.copy(t.environmentRotation),this.overrideMaterial=t.overrideMaterial!==null?t.overrideMaterial.clone():null,this.matrixAutoUpdate=t.matrixAutoUpdate,this}toJSON(t){let e=super.toJSON(t);return this.fog!==null&&(e.object.fog=this.fog.toJSON()),e.object.backgroundBlurriness=this.backgroundBlurriness,e.object.backgroundIntensity=this.backgroundIntensity,e.object.backgroundRotation=this.backgroundRotation.toArray(),e.object.environmentIntensity=this.environmentIntensity,e.object.environmentRotation=this.environmentRotation.toArray(),e}},Xn=new z,_i=new z,th=new z,vi=new z,Fa=new z,Ba=new z,Nu=new z,eh=new z,nh=new z,ih=new z,ah=new ce,sh=new ce,rh=new ce,ai=class i{constructor(t=new z,e=new z,n=new z){this.a=t,this.b=e,this.c=n}static getNormal(t,e,n,a){a.subVectors(n,e),Xn.subVectors(t,e),a.cross(Xn);let s=a.lengthSq();return s>0?a.multiplyScalar(1/Math.sqrt(s)):a.set(0,0,0)}static getBarycoord(t,e,n,a,s){Xn.subVectors(a,e),_i.subVectors(n,e),th.subVectors(t,e);let r=Xn.dot(Xn),o=Xn.dot(_i),c=Xn.dot(th),l=_i.dot(_i),h=_i.dot(th),u=r*l-o*o;if(u===0)return s.set(0,0,0),null;let d=1/u,f=(l*c-o*h)*d,x=(r*h-o*c)*d;return s.set(1-f-x,x,f)}static containsPoint(t,e,n,a){return this.getBarycoord(t,e,n,a,vi)===null?!1:vi.x>=0&&vi.y>=0&&vi.x+vi.y<=1}static getInterpolation(t,e,n,a,s,r,o,c){return this.getBarycoord(t,e,n,a,vi)===null?(c.x=0,c.y=0,"z"in c&&(c.z=0),"w"in c&&(c.w=0),null):(c.setScalar(0),c.addScaledVector(s,vi.x),c.addScaledVector(r,vi.y),c.addScaledVector(o,vi.z),c)}static getInterpolatedAttribute(t,e,n,a,s,r){return ah.setScalar(0),sh.setScalar(0),rh.setScalar(0),ah.fromBufferAttribute(t,e),sh.fromBufferAttribute(t,n),rh.fromBufferAttribute(t,a),r.setScalar(0),r.addScaledVector(ah,s.x),r.addScaledVector(sh,s.y),r.addScaledVector(rh,s.z),r}static isFrontFacing(t,e,n,a){return Xn.subVectors(n,e),_i.subVectors(t,e),Xn.cross(_i).dot(a)<0}set(t,e,n){return this.a.copy(t),this.b.copy(e),this.c.copy(n),this}setFromPointsAndIndices(t,e,n,a){return this.a.copy(t[e]),this.b.copy(t[n]),this.c.copy(t[a]),this}setFromAttributeAndIndices(t,e,n,a){return this.a.fromBufferAttribute(t,e),this.b.fromBufferAttribute(t,n),this.c.fromBufferAttribute(t,a),this}clone(){return new this.constructor().copy(this)}copy(t){return this.a.copy(t.a),this.b.copy(t.b),this.c.copy(t.c),this}getArea(){return Xn.subVectors(this.c,this.b),_i.subVectors(this.a,this.b),Xn.cross(_i).length()*.5}getMidpoint(t){return t.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(t){return i.getNormal(this.a,this.b,this.c,t)}getPlane(t){return t.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(t,e){return i.getBarycoord(t,this.a,this.b,this.c,e)}getInterpolation(t,e,n,a,s){return i.getInterpolation(t,this.a,this.b,this.c,e,n,a,s)}containsPoint(t){return i.containsPoint(t,this.a,this.b,this.c)}isFrontFacing(t){return i.isFrontFacing(this.a,this.b,this.c,t)}intersectsBox(t){return t.intersectsTriangle(this)}closestPointToPoint(t,e){let n=this.a,a=this.b,s=this.c,r,o;Fa.subVectors(a,n),Ba.subVectors(s,n),eh.subVectors(t,n);let c=Fa.dot(eh),l=Ba.dot(eh);if(c<=0&&l<=0)return e.copy(n);nh.subVectors(t,a);let h=Fa.dot(nh),u=Ba.dot(nh);if(h>=0&&u<=h)return e.copy(a);let d=c*u-h*l;if(d<=0&&c>=0&&h<=0&&c-h>0)return r=c/(c-h),e.copy(n).addScaledVector(Fa,r);ih.subVectors(t,s);let f=Fa.dot(ih),x=Ba.dot(ih);if(x>=0&&f<=x)return e.copy(s);let v=f*l-c*x;if(v<=0&&l>=0&&x<=0)return o=l/(l-x),e.copy(n).addScaledVector(Ba,o);let m=h*x-f*u;if(m<=0&&u-h>=0&&f-x>=0)return Nu.subVectors(s,a),o=(u-h)/(u-h+(f-x)),e.copy(a).addScaledVector(Nu,o);let g=1/(m+v+d);return r=v*g,o=d*g,e.copy(n).addScaledVector(Fa,r).addScaledVector(Ba,o)}equals(t){return t.a.equals(this.a)&&t.b.equals(this.b)&&t.c.equals(this.c)}},Oe=class{constructor(t=new z(1/0,1/0,1/0),e=new z(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=t,this.max=e}set(t,e){return this.min.copy(t),this.max.copy(e),this}setFromArray(t){this.makeEmpty();for(let e=0,n=t.length;e<n;e+=3)this.expandByPoint(qn.fromArray(t,e));return this}setFromBufferAttribute(t){this.makeEmpty();for(let e=0,n=t.count;e<n;e++)this.expandByPoint(qn.fromBufferAttribute(t,e));return this}setFromPoints(t){this.makeEmpty();for(let e=0,n=t.length;e<n;e++)this.expandByPoint(t[e]);return this}setFromCenterAndSize(t,e){let n=qn.copy(e).multiplyScalar(.5);return this.min.copy(t).sub(n),this.max.copy(t).add(n),this}setFromObject(t,e=!1){return this.makeEmpty(),this.expandByObject(t,e)}clone(){return new this.constructor().copy(this)}copy(t){return this.min.copy(t.min),this.max.copy(t.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(t){return this.isEmpty()?t.set(0,0,0):t.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(t){return this.isEmpty()?t.set(0,0,0):t.subVectors(this.max,this.min)}expandByPoint(t){return this.min.min(t),this.max.max(t),this}expandByVector(t){return this.min.sub(t),this.max.add(t),this}expandByScalar(t){return this.min.addScalar(-t),this.max.addScalar(t),this}expandByObject(t,e=!1){t.updateWorldMatrix(!1,!1);let n=t.geometry;if(n!==void 0){let s=n.getAttribute("position");if(e===!0&&s!==void 0&&t.isInstancedMesh!==!0&&t.isBatchedMesh!==!0)for(let r=0,o=s.count;r<o;r++)t.isMesh===!0?t.getVertexPosition(r,qn):qn.fromBufferAttribute(s,r),qn.applyMatrix4(t.matrixWorld),this.expandByPoint(qn);else t.boundingBox!==void 0?(t.boundingBox===null&&t.computeBoundingBox(),lo.copy(t.boundingBox)):(n.boundingBox===null&&n.computeBoundingBox(),lo.copy(n.boundingBox)),lo.applyMatrix4(t.matrixWorld),this.union(lo)}let a=t.children;for(let s=0,r=a.length;s<r;s++)this.expandByObject(a[s],e);return this}containsPoint(t){return t.x>=this.min.x&&t.x<=this.max.x&&t.y>=this.min.y&&t.y<=this.max.y&&t.z>=this.min.z&&t.z<=this.max.z}containsBox(t){return this.min.x<=t.min.x&&t.max.x<=this.max.x&&this.min.y<=t.min.y&&t.max.y<=this.max.y&&this.min.z<=t.min.z&&t.max.z<=this.max.z}getParameter(t,e){return e.set((t.x-this.min.x)/(this.max.x-this.min.x),(t.y-this.min.y)/(this.max.y-this.min.y),(t.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(t){return t.max.x>=this.min.x&&t.min.x<=this.max.x&&t.max.y>=this.min.y&&t.min.y<=this.max.y&&t.max.z>=this.min.z&&t.min.z<=this.max.z}intersectsSphere(t){return this.clampPoint(t.center,qn),qn.distanceToSquared(t.center)<=t.radius*t.radius}intersectsPlane(t){let e,n;return t.normal.x>0?(e=t.normal.x*this.min.x,n=t.normal.x*this.max.x):(e=t.normal.x*this.max.x,n=t.normal.x*this.min.x),t.normal.y>0?(e+=t.normal.y*this.min.y,n+=t.normal.y*this.max.y):(e+=t.normal.y*this.max.y,n+=t.normal.y*this.min.y),t.normal.z>0?(e+=t.normal.z*this.min.z,n+=t.normal.z*this.max.z):(e+=t.normal.z*this.max.z,n+=t.normal.z*this.min.z),e<=-t.constant&&n>=-t.constant}intersectsTriangle(t){if(this.isEmpty())return!1;this.getCenter(Hs),ho.subVectors(this.max,Hs),ka.subVectors(t.a,Hs),za.subVectors(t.b,Hs),Va.subVectors(t.c,Hs),zi.subVectors(za,ka),Vi.subVectors(Va,za),da.subVectors(ka,Va);let e=[0,-zi.z,zi.y,0,-Vi.z,Vi.y,0,-da.z,da.y,zi.z,0,-zi.x,Vi.z,0,-Vi.x,da.z,0,-da.x,-zi.y,zi.x,0,-Vi.y,Vi.x,0,-da.y,da.x,0];return!oh(e,ka,za,Va,ho)||(e=[1,0,0,0,1,0,0,0,1],!oh(e,ka,za,Va,ho))?!1:(uo.crossVectors(zi,Vi),e=[uo.x,uo.y,uo.z],oh(e,ka,za,Va,ho))}clampPoint(t,e){return e.copy(t).clamp(this.min,this.max)}distanceToPoint(t){return this.clampPoint(t,qn).distanceTo(t)}getBoundingSphere(t){return this.isEmpty()?t.makeEmpty():(this.getCenter(t.center),t.radius=this.getSize(qn).length()*.5),t}intersect(t){return this.min.max(t.min),this.max.min(t.max),this.isEmpty()&&this.makeEmpty(),this}union(t){return this.min.min(t.min),this.max.max(t.max),this}applyMatrix4(t){return this.isEmpty()?this:(Mi[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(t),Mi[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(t),Mi[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(t),Mi[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(t),Mi[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(t),Mi[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(t),Mi[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(t),Mi[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(t),this.setFromPoints(Mi),this)}translate(t){return this.min.add(t),this.max.add(t),this}equals(t){return t.min.equals(this.min)&&t.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(t){return this.min.fromArray(t.min),this.max.fromArray(t.max),this}},Mi=[new z,new z,new z,new z,new z,new z,new z,new z],qn=new z,lo=new Oe,ka=new z,za=new z,Va=new z,zi=new z,Vi=new z,da=new z,Hs=new z,ho=new z,uo=new z,ua=new z;Le=new z,fo=new Bt,Jg=0,pn=class extends Yn{constructor(t,e,n=!1){if(super(),Array.isArray(t))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:Jg++}),this.name="",this.array=t,this.itemSize=e,this.count=t!==void 0?t.length/e:0,this.normalized=n,this.usage=Kh,this.updateRanges=[],this.gpuType=gn,this.version=0,this._normalizationScale=t!==void 0?$c(t):void 0}onUploadCallback(){}set needsUpdate(t){t===!0&&this.version++}setUsage(t){return this.usage=t,this}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}copy(t){return this.name=t.name,this.array=new t.array.constructor(t.array),this.itemSize=t.itemSize,this.count=t.count,this.normalized=t.normalized,this.usage=t.usage,this.gpuType=t.gpuType,this._normalizationScale=t._normalizationScale,this}copyAt(t,e,n){t*=this.itemSize,n*=e.itemSize;for(let a=0,s=this.itemSize;a<s;a++)this.array[t+a]=e.array[n+a];return this}copyArray(t){return this.array.set(t),this}applyMatrix3(t){if(this.itemSize===2)for(let e=0,n=this.count;e<n;e++)fo.fromBufferAttribute(this,e),fo.applyMatrix3(t),this.setXY(e,fo.x,fo.y);else if(this.itemSize===3)for(let e=0,n=this.count;e<n;e++)Le.fromBufferAttribute(this,e),Le.applyMatrix3(t),this.setXYZ(e,Le.x,Le.y,Le.z);return this}applyMatrix4(t){for(let e=0,n=this.count;e<n;e++)Le.fromBufferAttribute(this,e),Le.applyMatrix4(t),this.setXYZ(e,Le.x,Le.y,Le.z);return this}applyNormalMatrix(t){for(let e=0,n=this.count;e<n;e++)Le.fromBufferAttribute(this,e),Le.applyNormalMatrix(t),this.setXYZ(e,Le.x,Le.y,Le.z);return this}transformDirection(t){for(let e=0,n=this.count;e<n;e++)Le.fromBufferAttribute(this,e),Le.transformDirection(t),this.setXYZ(e,Le.x,Le.y,Le.z);return this}set(t,e=0){return this.array.set(t,e),this}getComponent(t,e){let n=this.array[t*this.itemSize+e];return this.normalized&&(n=this._denormalize(n)),n}setComponent(t,e,n){return this.normalized&&(n=this._normalize(n)),this.array[t*this.itemSize+e]=n,this}getX(t){let e=this.array[t*this.itemSize];return this.normalized&&(e=this._denormalize(e)),e}setX(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize]=e,this}getY(t){let e=this.array[t*this.itemSize+1];return this.normalized&&(e=this._denormalize(e)),e}setY(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+1]=e,this}getZ(t){let e=this.array[t*this.itemSize+2];return this.normalized&&(e=this._denormalize(e)),e}setZ(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+2]=e,this}getW(t){let e=this.array[t*this.itemSize+3];return this.normalized&&(e=this._denormalize(e)),e}setW(t,e){return this.normalized&&(e=this._normalize(e)),this.array[t*this.itemSize+3]=e,this}setXY(t,e,n){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),n=this._normalize(n)),this.array[t+0]=e,this.array[t+1]=n,this}setXYZ(t,e,n,a){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),n=this._normalize(n),a=this._normalize(a)),this.array[t+0]=e,this.array[t+1]=n,this.array[t+2]=a,this}setXYZW(t,e,n,a,s){return t*=this.itemSize,this.normalized&&(e=this._normalize(e),n=this._normalize(n),a=this._normalize(a),s=this._normalize(s)),this.array[t+0]=e,this.array[t+1]=n,this.array[t+2]=a,this.array[t+3]=s,this}onUpload(t){return this.onUploadCallback=t,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){let t={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return t.name=this.name,t.usage=this.usage,t.gpuType=this.gpuType,t}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(t){let e=this._normalizationScale;return e!==void 0?Math.max(t/e,-1):td(t,this.array)}_normalize(t){let e=this._normalizationScale;return e!==void 0?Math.round(t*e):ed(t,this.array)}},nr=class extends pn{constructor(t,e,n){super(new Uint16Array(t),e,n)}},ir=class extends pn{constructor(t,e,n){super(new Uint32Array(t),e,n)}},xe=class extends pn{constructor(t,e,n){super(new Float32Array(t),e,n)}},Kg=new Oe,Gs=new z,ch=new z,Ge=class{constructor(t=new z,e=-1){this.isSphere=!0,this.center=t,this.radius=e}set(t,e){return this.center.copy(t),this.radius=e,this}setFromPoints(t,e){let n=this.center;e!==void 0?n.copy(e):Kg.setFromPoints(t).getCenter(n);let a=0;for(let s=0,r=t.length;s<r;s++)a=Math.max(a,n.distanceToSquared(t[s]));return this.radius=Math.sqrt(a),this}copy(t){return this.center.copy(t.center),this.radius=t.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(t){return t.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(t){return t.distanceTo(this.center)-this.radius}intersectsSphere(t){let e=this.radius+t.radius;return t.center.distanceToSquared(this.center)<=e*e}intersectsBox(t){return t.intersectsSphere(this)}intersectsPlane(t){return Math.abs(t.distanceToPoint(this.center))<=this.radius}clampPoint(t,e){let n=this.center.distanceToSquared(t);return e.copy(t),n>this.radius*this.radius&&(e.sub(this.center).normalize(),e.multiplyScalar(this.radius).add(this.center)),e}getBoundingBox(t){return this.isEmpty()?(t.makeEmpty(),t):(t.set(this.center,this.center),t.expandByScalar(this.radius),t)}applyMatrix4(t){return this.center.applyMatrix4(t),this.radius=this.radius*t.getMaxScaleOnAxis(),this}translate(t){return this.center.add(t),this}expandByPoint(t){if(this.isEmpty())return this.center.copy(t),this.radius=0,this;Gs.subVectors(t,this.center);let e=Gs.lengthSq();if(e>this.radius*this.radius){let n=Math.sqrt(e),a=(n-this.radius)*.5;this.center.addScaledVector(Gs,a/n),this.radius+=a}return this}union(t){return t.isEmpty()?this:this.isEmpty()?(this.copy(t),this):(this.center.equals(t.center)===!0?this.radius=Math.max(this.radius,t.radius):(ch.subVectors(t.center,this.center).setLength(t.radius),this.expandByPoint(Gs.copy(t.center).add(ch)),this.expandByPoint(Gs.copy(t.center).sub(ch))),this)}equals(t){return t.center.equals(this.center)&&t.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(t){return this.radius=t.radius,this.center.fromArray(t.center),this}},Zg=0,On=new oe,lh=new Fe,Ha=new z,In=new Oe,Ws=new Oe,He=new z,Ue=class i extends Yn{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:Zg++}),this.uuid=Ji(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(t){return Array.isArray(t)?this.index=new(Mg(t)?ir:nr)(t,1):this.index=t,this}setIndirect(t,e=0){return this.indirect=t,this.indirectOffset=e,this}getIndirect(){return this.indirect}getAttribute(t){return this.attributes[t]}setAttribute(t,e){return this.attributes[t]=e,this}deleteAttribute(t){return delete this.attributes[t],this}hasAttribute(t){return this.attributes[t]!==void 0}addGroup(t,e,n=0){this.groups.push({start:t,count:e,materialIndex:n})}clearGroups(){this.groups=[]}setDrawRange(t,e){this.drawRange.start=t,this.drawRange.count=e}applyMatrix4(t){let e=this.attributes.position;e!==void 0&&(e.applyMatrix4(t),e.needsUpdate=!0);let n=this.attributes.normal;if(n!==void 0){let s=new Vt().getNormalMatrix(t);n.applyNormalMatrix(s),n.needsUpdate=!0}let a=this.attributes.tangent;return a!==void 0&&(a.transformDirection(t),a.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(t){return On.makeRotationFromQuaternion(t),this.applyMatrix4(On),this}rotateX(t){return On.makeRotationX(t),this.applyMatrix4(On),this}rotateY(t){return On.makeRotationY(t),this.applyMatrix4(On),this}rotateZ(t){return On.makeRotationZ(t),this.applyMatrix4(On),this}translate(t,e,n){return On.makeTranslation(t,e,n),this.applyMatrix4(On),this}scale(t,e,n){return On.makeScale(t,e,n),this.applyMatrix4(On),this}lookAt(t){return lh.lookAt(t),lh.updateMatrix(),this.applyMatrix4(lh.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(Ha).negate(),this.translate(Ha.x,Ha.y,Ha.z),this}setFromPoints(t){let e=this.getAttribute("position");if(e===void 0){let n=[];for(let a=0,s=t.length;a<s;a++){let r=t[a];n.push(r.x,r.y,r.z||0)}this.setAttribute("position",new xe(n,3))}else{let n=Math.min(t.length,e.count);for(let a=0;a<n;a++){let s=t[a];e.setXYZ(a,s.x,s.y,s.z||0)}t.length>e.count&&Ft("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),e.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Oe);let t=this.attributes.position,e=this.morphAttributes.position;if(t&&t.isGLBufferAttribute){zt("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new z(-1/0,-1/0,-1/0),new z(1/0,1/0,1/0));return}if(t!==void 0){if(this.boundingBox.setFromBufferAttribute(t),e)for(let n=0,a=e.length;n<a;n++){let s=e[n];In.setFromBufferAttribute(s),this.morphTargetsRelative?(He.addVectors(this.boundingBox.min,In.min),this.boundingBox.expandByPoint(He),He.addVectors(this.boundingBox.max,In.max),this.boundingBox.expandByPoint(He)):(this.boundingBox.expandByPoint(In.min),this.boundingBox.expandByPoint(In.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&zt('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new Ge);let t=this.attributes.position,e=this.morphAttributes.position;if(t&&t.isGLBufferAttribute){zt("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new z,1/0);return}if(t){let n=this.boundingSphere.center;if(In.setFromBufferAttribute(t),e)for(let s=0,r=e.length;s<r;s++){let o=e[s];Ws.setFromBufferAttribute(o),this.morphTargetsRelative?(He.addVectors(In.min,Ws.min),In.expandByPoint(He),He.addVectors(In.max,Ws.max),In.expandByPoint(He)):(In.expandByPoint(Ws.min),In.expandByPoint(Ws.max))}In.getCenter(n);let a=0;for(let s=0,r=t.count;s<r;s++)He.fromBufferAttribute(t,s),a=Math.max(a,n.distanceToSquared(He));if(e)for(let s=0,r=e.length;s<r;s++){let o=e[s],c=this.morphTargetsRelative;for(let l=0,h=o.count;l<h;l++)He.fromBufferAttribute(o,l),c&&(Ha.fromBufferAttribute(t,l),He.add(Ha)),a=Math.max(a,n.distanceToSquared(He))}this.boundingSphere.radius=Math.sqrt(a),isNaN(this.boundingSphere.radius)&&zt('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){let t=this.index,e=this.attributes;if(t===null||e.position===void 0||e.normal===void 0||e.uv===void 0){zt("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}let n=e.position,a=e.normal,s=e.uv,r=this.getAttribute("tangent");(r===void 0||r.count!==n.count)&&(r=new pn(new Float32Array(4*n.count),4),this.setAttribute("tangent",r));let o=[],c=[],l=new Uint8Array(n.count);for(let E=0;E<n.count;E++)o[E]=new z,c[E]=new z;let h=new z,u=new z,d=new z,f=new Bt,x=new Bt,v=new Bt,m=new z,g=new z;function y(E,A,I){l[E]=l[A]=l[I]=1,h.fromBufferAttribute(n,E),u.fromBufferAttribute(n,A),d.fromBufferAttribute(n,I),f.fromBufferAttribute(s,E),x.fromBufferAttribute(s,A),v.fromBufferAttribute(s,I),u.sub(h),d.sub(h),x.sub(f),v.sub(f);let N=1/(x.x*v.y-v.x*x.y);isFinite(N)&&(m.copy(u).multiplyScalar(v.y).addScaledVector(d,-x.y).multiplyScalar(N),g.copy(d).multiplyScalar(x.x).addScaledVector(u,-v.x).multiplyScalar(N),o[E].add(m),o[A].add(m),o[I].add(m),c[E].add(g),c[A].add(g),c[I].add(g))}let w=this.groups;w.length===0&&(w=[{start:0,count:t.count}]);for(let E=0,A=w.length;E<A;++E){let I=w[E],N=I.start,L=I.count;for(let P=N,U=N+L;P<U;P+=3)y(t.getX(P+0),t.getX(P+1),t.getX(P+2))}let p=new z,_=new z,S=new z,b=new z;function M(E){S.fromBufferAttribute(a,E),b.copy(S);let A=o[E];p.copy(A),p.sub(S.multiplyScalar(S.dot(A))).normalize(),_.crossVectors(b,A);let N=_.dot(c[E])<0?-1:1;r.setXYZW(E,p.x,p.y,p.z,N)}for(let E=0,A=n.count;E<A;++E)l[E]&&M(E);this._transformed=!0}computeVertexNormals(){let t=this.index,e=this.getAttribute("position");if(e!==void 0){let n=this.getAttribute("normal");if(n===void 0||n.count!==e.count)n=new pn(new Float32Array(e.count*3),3),this.setAttribute("normal",n);else for(let d=0,f=n.count;d<f;d++)n.setXYZ(d,0,0,0);let a=new z,s=new z,r=new z,o=new z,c=new z,l=new z,h=new z,u=new z;if(t)for(let d=0,f=t.count;d<f;d+=3){let x=t.getX(d+0),v=t.getX(d+1),m=t.getX(d+2);a.fromBufferAttribute(e,x),s.fromBufferAttribute(e,v),r.fromBufferAttribute(e,m),h.subVectors(r,s),u.subVectors(a,s),h.cross(u),o.fromBufferAttribute(n,x),c.fromBufferAttribute(n,v),l.fromBufferAttribute(n,m),o.add(h),c.add(h),l.add(h),n.setXYZ(x,o.x,o.y,o.z),n.setXYZ(v,c.x,c.y,c.z),n.setXYZ(m,l.x,l.y,l.z)}else for(let d=0,f=e.count;d<f;d+=3)a.fromBufferAttribute(e,d+0),s.fromBufferAttribute(e,d+1),r.fromBufferAttribute(e,d+2),h.subVectors(r,s),u.subVectors(a,s),h.cross(u),n.setXYZ(d+0,h.x,h.y,h.z),n.setXYZ(d+1,h.x,h.y,h.z),n.setXYZ(d+2,h.x,h.y,h.z);this.normalizeNormals(),n.needsUpdate=!0}}normalizeNormals(){let t=this.attributes.normal;for(let e=0,n=t.count;e<n;e++)He.fromBufferAttribute(t,e),He.normalize(),t.setXYZ(e,He.x,He.y,He.z)}toNonIndexed(){function t(o,c){let l=o.array,h=o.itemSize,u=o.normalized,d=new l.constructor(c.length*h),f=0,x=0;for(let v=0,m=c.length;v<m;v++){o.isInterleavedBufferAttribute?f=c[v]*o.data.stride+o.offset:f=c[v]*h;for(let g=0;g<h;g++)d[x++]=l[f++]}return new pn(d,h,u)}if(this.index===null)return Ft("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;let e=new i,n=this.index.array,a=this.attributes;for(let o in a){let c=a[o],l=t(c,n);e.setAttribute(o,l)}let s=this.morphAttributes;for(let o in s){let c=[],l=s[o];for(let h=0,u=l.length;h<u;h++){let d=l[h],f=t(d,n);c.push(f)}e.morphAttributes[o]=c}e.morphTargetsRelative=this.morphTargetsRelative;let r=this.groups;for(let o=0,c=r.length;o<c;o++){let l=r[o];e.addGroup(l.start,l.count,l.materialIndex)}return e}toJSON(){let t={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(t.uuid=this.uuid,t.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,t.name=this.name,Object.keys(this.userData).length>0&&(t.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){let c=this.parameters;for(let l in c)c[l]!==void 0&&(t[l]=c[l]);return t}t.data={attributes:{}};let e=this.index;e!==null&&(t.data.index={type:e.array.constructor.name,array:Array.prototype.slice.call(e.array)});let n=this.attributes;for(let c in n){let l=n[c];t.data.attributes[c]=l.toJSON(t.data)}let a={},s=!1;for(let c in this.morphAttributes){let l=this.morphAttributes[c],h=[];for(let u=0,d=l.length;u<d;u++){let f=l[u];h.push(f.toJSON(t.data))}h.length>0&&(a[c]=h,s=!0)}s&&(t.data.morphAttributes=a,t.data.morphTargetsRelative=this.morphTargetsRelative);let r=this.groups;r.length>0&&(t.data.groups=JSON.parse(JSON.stringify(r)));let o=this.boundingSphere;return o!==null&&(t.data.boundingSphere=o.toJSON()),t}clone(){return new this.constructor().copy(this)}copy(t){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;let e={};this.name=t.name;let n=t.index;n!==null&&this.setIndex(n.clone());let a=t.attributes;for(let l in a){let h=a[l];this.setAttribute(l,h.clone(e))}let s=t.morphAttributes;for(let l in s){let h=[],u=s[l];for(let d=0,f=u.length;d<f;d++)h.push(u[d].clone(e));this.morphAttributes[l]=h}this.morphTargetsRelative=t.morphTargetsRelative;let r=t.groups;for(let l=0,h=r.length;l<h;l++){let u=r[l];this.addGroup(u.start,u.count,u.materialIndex)}let o=t.boundingBox;o!==null&&(this.boundingBox=o.clone());let c=t.boundingSphere;return c!==null&&(this.boundingSphere=c.clone()),this.drawRange.start=t.drawRange.start,this.drawRange.count=t.drawRange.count,this.userData=t.userData,this._transformed=t._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}},Jo=class{constructor(t,e){this.isInterleavedBuffer=!0,this.array=t,this.stride=e,this.count=t!==void 0?t.length/e:0,this.usage=Kh,this.updateRanges=[],this.version=0,this.uuid=Ji()}onUploadCallback(){}set needsUpdate(t){t===!0&&this.version++}setUsage(t){return this.usage=t,this}addUpdateRange(t,e){this.updateRanges.push({start:t,count:e})}clearUpdateRanges(){this.updateRanges.length=0}copy(t){return this.array=new t.array.constructor(t.array),this.count=t.count,this.stride=t.stride,this.usage=t.usage,this}copyAt(t,e,n){t*=this.stride,n*=e.stride;for(let a=0,s=this.stride;a<s;a++)this.array[t+a]=e.array[n+a];return this}set(t,e=0){return this.array.set(t,e),this}clone(t){t.arrayBuffers===void 0&&(t.arrayBuffers={});let e=Pu(this.array);t.arrayBuffers[e]===void 0&&(t.arrayBuffers[e]=this.array.slice(0).buffer);let n=new this.array.constructor(t.arrayBuffers[e]),a=new this.constructor(n,this.stride);return a.setUsage(this.usage),a}onUpload(t){return this.onUploadCallback=t,this}toJSON(t){t.arrayBuffers===void 0&&(t.arrayBuffers={});let e=Pu(this.array);t.arrayBuffers[e]===void 0&&(t.arrayBuffers[e]=Array.from(new Uint32Array(this.array.slice(0).buffer)));let n={uuid:this.uuid,buffer:e,type:this.array.constructor.name,stride:this.stride};return n.usage=this.usage,n}};dn=new z,Jn=class i{constructor(t,e,n,a=!1){this.isInterleavedBufferAttribute=!0,this.name="",this.data=t,this.itemSize=e,this.offset=n,this.normalized=a,this._normalizationScale=t!==void 0?$c(t.array):void 0}get count(){return this.data.count}get array(){return this.data.array}set needsUpdate(t){this.data.needsUpdate=t}applyMatrix4(t){for(let e=0,n=this.data.count;e<n;e++)dn.fromBufferAttribute(this,e),dn.applyMatrix4(t),this.setXYZ(e,dn.x,dn.y,dn.z);return this}applyNormalMatrix(t){for(let e=0,n=this.count;e<n;e++)dn.fromBufferAttribute(this,e),dn.applyNormalMatrix(t),this.setXYZ(e,dn.x,dn.y,dn.z);return this}transformDirection(t){for(let e=0,n=this.count;e<n;e++)dn.fromBufferAttribute(this,e),dn.transformDirection(t),this.setXYZ(e,dn.x,dn.y,dn.z);return this}getComponent(t,e){let n=this.array[t*this.data.stride+this.offset+e];return this.normalized&&(n=this._denormalize(n)),n}setComponent(t,e,n){return this.normalized&&(n=this._normalize(n)),this.data.array[t*this.data.stride+this.offset+e]=n,this}setX(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset]=e,this}setY(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset+1]=e,this}setZ(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset+2]=e,this}setW(t,e){return this.normalized&&(e=this._normalize(e)),this.data.array[t*this.data.stride+this.offset+3]=e,this}getX(t){let e=this.data.array[t*this.data.stride+this.offset];return this.normalized&&(e=this._denormalize(e)),e}getY(t){let e=this.data.array[t*this.data.stride+this.offset+1];return this.normalized&&(e=this._denormalize(e)),e}getZ(t){let e=this.data.array[t*this.data.stride+this.offset+2];return this.normalized&&(e=this._denormalize(e)),e}getW(t){let e=this.data.array[t*this.data.stride+this.offset+3];return this.normalized&&(e=this._denormalize(e)),e}setXY(t,e,n){return t=t*this.data.stride+this.offset,this.normalized&&(e=this._normalize(e),n=this._normalize(n)),this.data.array[t+0]=e,this.data.array[t+1]=n,this}setXYZ(t,e,n,a){return t=t*this.data.stride+this.offset,this.normalized&&(e=this._normalize(e),n=this._normalize(n),a=this._normalize(a)),this.data.array[t+0]=e,this.data.array[t+1]=n,this.data.array[t+2]=a,this}setXYZW(t,e,n,a,s){return t=t*this.data.stride+this.offset,this.normalized&&(e=this._normalize(e),n=this._normalize(n),a=this._normalize(a),s=this._normalize(s)),this.data.array[t+0]=e,this.data.array[t+1]=n,this.data.array[t+2]=a,this.data.array[t+3]=s,this}clone(t){if(t===void 0){$s("InterleavedBufferAttribute.clone(): Cloning an interleaved buffer attribute will de-interleave buffer data.");let e=[];for(let n=0;n<this.count;n++){let a=n*this.data.stride+this.offset;for(let s=0;s<this.itemSize;s++)e.push(this.data.array[a+s])}return new pn(new this.array.constructor(e),this.itemSize,this.normalized)}else return t.interleavedBuffers===void 0&&(t.interleavedBuffers={}),t.interleavedBuffers[this.data.uuid]===void 0&&(t.interleavedBuffers[this.data.uuid]=this.data.clone(t)),new i(t.interleavedBuffers[this.data.uuid],this.itemSize,this.offset,this.normalized)}toJSON(t){if(t===void 0){$s("InterleavedBufferAttribute.toJSON(): Serializing an interleaved buffer attribute will de-interleave buffer data.");let e=[];for(let n=0;n<this.count;n++){let a=n*this.data.stride+this.offset;for(let s=0;s<this.itemSize;s++)e.push(this.data.array[a+s])}return{itemSize:this.itemSize,type:this.array.constructor.name,array:e,normalized:this.normalized}}else return t.interleavedBuffers===void 0&&(t.interleavedBuffers={}),t.interleavedBuffers[this.data.uuid]===void 0&&(t.interleavedBuffers[this.data.uuid]=this.data.toJSON(t)),{isInterleavedBufferAttribute:!0,itemSize:this.itemSize,data:this.data.uuid,offset:this.offset,normalized:this.normalized}}_denormalize(t){let e=this._normalizationScale;return e!==void 0?Math.max(t/e,-1):td(t,this.data.array)}_normalize(t){let e=this._normalizationScale;return e!==void 0?Math.round(t*e):ed(t,this.data.array)}},hh=new z,Qg=new z,$g=new Vt,un=class{constructor(t=new z(1,0,0),e=0){this.isPlane=!0,this.normal=t,this.constant=e}set(t,e){return this.normal.copy(t),this.constant=e,this}setComponents(t,e,n,a){return this.normal.set(t,e,n),this.constant=a,this}setFromNormalAndCoplanarPoint(t,e){return this.normal.copy(t),this.constant=-e.dot(this.normal),this}setFromCoplanarPoints(t,e,n){let a=hh.subVectors(n,e).cross(Qg.subVectors(t,e)).normalize();return this.setFromNormalAndCoplanarPoint(a,t),this}copy(t){return this.normal.copy(t.normal),this.constant=t.constant,this}normalize(){let t=1/this.normal.length();return this.normal.multiplyScalar(t),this.constant*=t,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(t){return this.normal.dot(t)+this.constant}distanceToSphere(t){return this.distanceToPoint(t.center)-t.radius}projectPoint(t,e){return e.copy(t).addScaledVector(this.normal,-this.distanceToPoint(t))}intersectLine(t,e,n=!0){let a=t.delta(hh),s=this.normal.dot(a);if(s===0)return this.distanceToPoint(t.start)===0?e.copy(t.start):null;let r=-(t.start.dot(this.normal)+this.constant)/s;return n===!0&&(r<0||r>1)?null:e.copy(t.start).addScaledVector(a,r)}intersectsLine(t){let e=this.distanceToPoint(t.start),n=this.distanceToPoint(t.end);return e<0&&n>0||n<0&&e>0}intersectsBox(t){return t.intersectsPlane(this)}intersectsSphere(t){return t.intersectsPlane(this)}coplanarPoint(t){return t.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(t,e){let n=e||$g.getNormalMatrix(t),a=this.coplanarPoint(hh).applyMatrix4(t),s=this.normal.applyMatrix3(n).normalize();return this.constant=-a.dot(s),this}translate(t){return this.constant-=t.dot(this.normal),this}equals(t){return t.normal.equals(this.normal)&&t.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(t){return this.normal.fromArray(t.normal),this.constant=t.constant,this}},tb=0,ri=class extends Yn{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:tb++}),this.uuid=Ji(),this.name="",this.type="Material",this.blending=ls,this.side=ci,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=Lh,this.blendDst=Dh,this.blendEquation=_a,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new jt(0,0,0),this.blendAlpha=0,this.depthFunc=Ja,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=Rf,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=Uo,this.stencilZFail=Uo,this.stencilZPass=Uo,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(t){this._alphaTest>0!=t>0&&this.version++,this._alphaTest=t}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(t){if(t!==void 0)for(let e in t){let n=t[e];if(n===void 0){Ft(`Material: parameter '${e}' has value of undefined.`);continue}let a=this[e];if(a===void 0){Ft(`Material: '${e}' is not a property of THREE.${this.type}.`);continue}a&&a.isColor?a.set(n):a&&a.isVector2&&n&&n.isVector2||a&&a.isEuler&&n&&n.isEuler||a&&a.isVector3&&n&&n.isVector3?a.copy(n):this[e]=n}}toJSON(t){let e=t===void 0||typeof t=="string";e&&(t={textures:{},images:{}});let n={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};n.uuid=this.uuid,n.type=this.type,n.blending=this.blending,n.side=this.side,n.shadowSide=this.shadowSide,n.vertexColors=this.vertexColors,n.opacity=this.opacity,n.transparent=this.transparent,n.blendSrc=this.blendSrc,n.blendDst=this.blendDst,n.blendEquation=this.blendEquation,n.blendSrcAlpha=this.blendSrcAlpha,n.blendDstAlpha=this.blendDstAlpha,n.blendEquationAlpha=this.blendEquationAlpha,n.blendColor=this.blendColor.getHex(),n.blendAlpha=this.blendAlpha,n.depthFunc=this.depthFunc,n.depthTest=this.depthTest,n.depthWrite=this.depthWrite,n.colorWrite=this.colorWrite,n.clipIntersection=this.clipIntersection,n.clipShadows=this.clipShadows,n.stencilWriteMask=this.stencilWriteMask,n.stencilFunc=this.stencilFunc,n.stencilRef=this.stencilRef,n.stencilFuncMask=this.stencilFuncMask,n.stencilFail=this.stencilFail,n.stencilZFail=this.stencilZFail,n.stencilZPass=this.stencilZPass,n.stencilWrite=this.stencilWrite,n.polygonOffset=this.polygonOffset,n.polygonOffsetFactor=this.polygonOffsetFactor,n.polygonOffsetUnits=this.polygonOffsetUnits,n.dithering=this.dithering,n.alphaTest=this.alphaTest,n.alphaHash=this.alphaHash,n.alphaToCoverage=this.alphaToCoverage,n.premultipliedAlpha=this.premultipliedAlpha,n.forceSinglePass=this.forceSinglePass,n.allowOverride=this.allowOverride,n.visible=this.visible,n.toneMapped=this.toneMapped,n.name=this.name,this.color&&this.color.isColor&&(n.color=this.color.getHex()),this.roughness!==void 0&&(n.roughness=this.roughness),this.metalness!==void 0&&(n.metalness=this.metalness),this.sheen!==void 0&&(n.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(n.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(n.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(n.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(n.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(n.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(n.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(n.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(n.shininess=this.shininess),this.clearcoat!==void 0&&(n.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(n.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(n.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(n.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(t).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(n.clearcoatMap=this.clearcoatMap.toJSON(t).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(n.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(t).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(n.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(t).uuid,n.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(n.sheenColorMap=this.sheenColorMap.toJSON(t).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(n.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(t).uuid),this.dispersion!==void 0&&(n.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(n.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(n.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(n.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(n.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(n.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(n.iridescenceMap=this.iridescenceMap.toJSON(t).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(n.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(t).uuid),this.anisotropy!==void 0&&(n.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(n.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(n.anisotropyMap=this.anisotropyMap.toJSON(t).uuid),this.map&&this.map.isTexture&&(n.map=this.map.toJSON(t).uuid),this.matcap&&this.matcap.isTexture&&(n.matcap=this.matcap.toJSON(t).uuid),this.alphaMap&&this.alphaMap.isTexture&&(n.alphaMap=this.alphaMap.toJSON(t).uuid),this.lightMap&&this.lightMap.isTexture&&(n.lightMap=this.lightMap.toJSON(t).uuid,n.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(n.aoMap=this.aoMap.toJSON(t).uuid,n.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(n.bumpMap=this.bumpMap.toJSON(t).uuid,n.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(n.normalMap=this.normalMap.toJSON(t).uuid,n.normalMapType=this.normalMapType,n.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(n.displacementMap=this.displacementMap.toJSON(t).uuid,n.displacementScale=this.displacementScale,n.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(n.roughnessMap=this.roughnessMap.toJSON(t).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(n.metalnessMap=this.metalnessMap.toJSON(t).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(n.emissiveMap=this.emissiveMap.toJSON(t).uuid),this.specularMap&&this.specularMap.isTexture&&(n.specularMap=this.specularMap.toJSON(t).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(n.specularIntensityMap=this.specularIntensityMap.toJSON(t).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(n.specularColorMap=this.specularColorMap.toJSON(t).uuid),this.envMap&&this.envMap.isTexture&&(n.envMap=this.envMap.toJSON(t).uuid,this.combine!==void 0&&(n.combine=this.combine)),this.envMapRotation!==void 0&&(n.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(n.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(n.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(n.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(n.gradientMap=this.gradientMap.toJSON(t).uuid),this.transmission!==void 0&&(n.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(n.transmissionMap=this.transmissionMap.toJSON(t).uuid),this.thickness!==void 0&&(n.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(n.thicknessMap=this.thicknessMap.toJSON(t).uuid),this.attenuationDistance!==void 0&&(n.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(n.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(n.size=this.size),this.sizeAttenuation!==void 0&&(n.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(n.clippingPlanes=this.clippingPlanes.map(s=>s.toJSON())),this.rotation!==void 0&&(n.rotation=this.rotation),this.depthPacking!==void 0&&(n.depthPacking=this.depthPacking),this.linewidth!==void 0&&(n.linewidth=this.linewidth),this.linecap!==void 0&&(n.linecap=this.linecap),this.linejoin!==void 0&&(n.linejoin=this.linejoin),this.dashSize!==void 0&&(n.dashSize=this.dashSize),this.gapSize!==void 0&&(n.gapSize=this.gapSize),this.scale!==void 0&&(n.scale=this.scale),this.wireframe!==void 0&&(n.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(n.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(n.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(n.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(n.flatShading=this.flatShading),this.fog!==void 0&&(n.fog=this.fog),Object.keys(this.userData).length>0&&(n.userData=this.userData);function a(s){let r=[];for(let o in s){let c=s[o];delete c.metadata,r.push(c)}return r}if(e){let s=a(t.textures),r=a(t.images);s.length>0&&(n.textures=s),r.length>0&&(n.images=r)}return n}fromJSON(t,e){if(t.uuid!==void 0&&(this.uuid=t.uuid),t.name!==void 0&&(this.name=t.name),t.color!==void 0&&this.color!==void 0&&this.color.setHex(t.color),t.roughness!==void 0&&(this.roughness=t.roughness),t.metalness!==void 0&&(this.metalness=t.metalness),t.sheen!==void 0&&(this.sheen=t.sheen),t.sheenColor!==void 0&&(this.sheenColor=new jt().setHex(t.sheenColor)),t.sheenRoughness!==void 0&&(this.sheenRoughness=t.sheenRoughness),t.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(t.emissive),t.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(t.specular),t.specularIntensity!==void 0&&(this.specularIntensity=t.specularIntensity),t.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(t.specularColor),t.shininess!==void 0&&(this.shininess=t.shininess),t.clearcoat!==void 0&&(this.clearcoat=t.clearcoat),t.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=t.clearcoatRoughness),t.diffuseRoughness!==void 0&&(this.diffuseRoughness=t.diffuseRoughness),t.dispersion!==void 0&&(this.dispersion=t.dispersion),t.retroreflectivity!==void 0&&(this.retroreflectivity=t.retroreflectivity),t.iridescence!==void 0&&(this.iridescence=t.iridescence),t.iridescenceIOR!==void 0&&(this.iridescenceIOR=t.iridescenceIOR),t.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=t.iridescenceThicknessMinimum),t.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=t.iridescenceThicknessMaximum),t.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=t.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=t.iridescenceThicknessRange[1]),t.transmission!==void 0&&(this.transmission=t.transmission),t.thickness!==void 0&&(this.thickness=t.thickness),t.attenuationDistance!==void 0&&(this.attenuationDistance=t.attenuationDistance),t.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(t.attenuationColor),t.anisotropy!==void 0&&(this.anisotropy=t.anisotropy),t.anisotropyRotation!==void 0&&(this.anisotropyRotation=t.anisotropyRotation),t.fog!==void 0&&(this.fog=t.fog),t.flatShading!==void 0&&(this.flatShading=t.flatShading),t.blending!==void 0&&(this.blending=t.blending),t.combine!==void 0&&(this.combine=t.combine),t.side!==void 0&&(this.side=t.side),t.shadowSide!==void 0&&(this.shadowSide=t.shadowSide),t.opacity!==void 0&&(this.opacity=t.opacity),t.transparent!==void 0&&(this.transparent=t.transparent),t.alphaTest!==void 0&&(this.alphaTest=t.alphaTest),t.alphaHash!==void 0&&(this.alphaHash=t.alphaHash),t.depthFunc!==void 0&&(this.depthFunc=t.depthFunc),t.depthTest!==void 0&&(this.depthTest=t.depthTest),t.depthWrite!==void 0&&(this.depthWrite=t.depthWrite),t.colorWrite!==void 0&&(this.colorWrite=t.colorWrite),t.clippingPlanes!==void 0&&(this.clippingPlanes=t.clippingPlanes.map(n=>new un().fromJSON(n))),t.clipIntersection!==void 0&&(this.clipIntersection=t.clipIntersection),t.clipShadows!==void 0&&(this.clipShadows=t.clipShadows),t.depthPacking!==void 0&&(this.depthPacking=t.depthPacking),t.blendSrc!==void 0&&(this.blendSrc=t.blendSrc),t.blendDst!==void 0&&(this.blendDst=t.blendDst),t.blendEquation!==void 0&&(this.blendEquation=t.blendEquation),t.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=t.blendSrcAlpha),t.blendDstAlpha!==void 0&&(this.blendDstAlpha=t.blendDstAlpha),t.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=t.blendEquationAlpha),t.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(t.blendColor),t.blendAlpha!==void 0&&(this.blendAlpha=t.blendAlpha),t.stencilWriteMask!==void 0&&(this.stencilWriteMask=t.stencilWriteMask),t.stencilFunc!==void 0&&(this.stencilFunc=t.stencilFunc),t.stencilRef!==void 0&&(this.stencilRef=t.stencilRef),t.stencilFuncMask!==void 0&&(this.stencilFuncMask=t.stencilFuncMask),t.stencilFail!==void 0&&(this.stencilFail=t.stencilFail),t.stencilZFail!==void 0&&(this.stencilZFail=t.stencilZFail),t.stencilZPass!==void 0&&(this.stencilZPass=t.stencilZPass),t.stencilWrite!==void 0&&(this.stencilWrite=t.stencilWrite),t.wireframe!==void 0&&(this.wireframe=t.wireframe),t.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=t.wireframeLinewidth),t.wireframeLinecap!==void 0&&(this.wireframeLinecap=t.wireframeLinecap),t.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=t.wireframeLinejoin),t.rotation!==void 0&&(this.rotation=t.rotation),t.linewidth!==void 0&&(this.linewidth=t.linewidth),t.linecap!==void 0&&(this.linecap=t.linecap),t.linejoin!==void 0&&(this.linejoin=t.linejoin),t.dashSize!==void 0&&(this.dashSize=t.dashSize),t.gapSize!==void 0&&(this.gapSize=t.gapSize),t.scale!==void 0&&(this.scale=t.scale),t.polygonOffset!==void 0&&(this.polygonOffset=t.polygonOffset),t.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=t.polygonOffsetFactor),t.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=t.polygonOffsetUnits),t.dithering!==void 0&&(this.dithering=t.dithering),t.alphaToCoverage!==void 0&&(this.alphaToCoverage=t.alphaToCoverage),t.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=t.premultipliedAlpha),t.forceSinglePass!==void 0&&(this.forceSinglePass=t.forceSinglePass),t.allowOverride!==void 0&&(this.allowOverride=t.allowOverride),t.visible!==void 0&&(this.visible=t.visible),t.toneMapped!==void 0&&(this.toneMapped=t.toneMapped),t.userData!==void 0&&(this.userData=t.userData),t.vertexColors!==void 0&&(typeof t.vertexColors=="number"?this.vertexColors=t.vertexColors>0:this.vertexColors=t.vertexColors),t.size!==void 0&&(this.size=t.size),t.sizeAttenuation!==void 0&&(this.sizeAttenuation=t.sizeAttenuation),t.map!==void 0&&(this.map=e[t.map]||null),t.matcap!==void 0&&(this.matcap=e[t.matcap]||null),t.alphaMap!==void 0&&(this.alphaMap=e[t.alphaMap]||null),t.bumpMap!==void 0&&(this.bumpMap=e[t.bumpMap]||null),t.bumpScale!==void 0&&(this.bumpScale=t.bumpScale),t.normalMap!==void 0&&(this.normalMap=e[t.normalMap]||null),t.normalMapType!==void 0&&(this.normalMapType=t.normalMapType),t.normalScale!==void 0){let n=t.normalScale;Array.isArray(n)===!1&&(n=[n,n]),this.normalScale=new Bt().fromArray(n)}return t.displacementMap!==void 0&&(this.displacementMap=e[t.displacementMap]||null),t.displacementScale!==void 0&&(this.displacementScale=t.displacementScale),t.displacementBias!==void 0&&(this.displacementBias=t.displacementBias),t.roughnessMap!==void 0&&(this.roughnessMap=e[t.roughnessMap]||null),t.metalnessMap!==void 0&&(this.metalnessMap=e[t.metalnessMap]||null),t.emissiveMap!==void 0&&(this.emissiveMap=e[t.emissiveMap]||null),t.emissiveIntensity!==void 0&&(this.emissiveIntensity=t.emissiveIntensity),t.specularMap!==void 0&&(this.specularMap=e[t.specularMap]||null),t.specularIntensityMap!==void 0&&(this.specularIntensityMap=e[t.specularIntensityMap]||null),t.specularColorMap!==void 0&&(this.specularColorMap=e[t.specularColorMap]||null),t.envMap!==void 0&&(this.envMap=e[t.envMap]||null),t.envMapRotation!==void 0&&this.envMapRotation.fromArray(t.envMapRotation),t.envMapIntensity!==void 0&&(this.envMapIntensity=t.envMapIntensity),t.reflectivity!==void 0&&(this.reflectivity=t.reflectivity),t.refractionRatio!==void 0&&(this.refractionRatio=t.refractionRatio),t.lightMap!==void 0&&(this.lightMap=e[t.lightMap]||null),t.lightMapIntensity!==void 0&&(this.lightMapIntensity=t.lightMapIntensity),t.aoMap!==void 0&&(this.aoMap=e[t.aoMap]||null),t.aoMapIntensity!==void 0&&(this.aoMapIntensity=t.aoMapIntensity),t.gradientMap!==void 0&&(this.gradientMap=e[t.gradientMap]||null),t.clearcoatMap!==void 0&&(this.clearcoatMap=e[t.clearcoatMap]||null),t.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=e[t.clearcoatRoughnessMap]||null),t.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=e[t.clearcoatNormalMap]||null),t.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new Bt().fromArray(t.clearcoatNormalScale)),t.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=e[t.diffuseRoughnessMap]||null),t.iridescenceMap!==void 0&&(this.iridescenceMap=e[t.iridescenceMap]||null),t.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=e[t.iridescenceThicknessMap]||null),t.transmissionMap!==void 0&&(this.transmissionMap=e[t.transmissionMap]||null),t.thicknessMap!==void 0&&(this.thicknessMap=e[t.thicknessMap]||null),t.anisotropyMap!==void 0&&(this.anisotropyMap=e[t.anisotropyMap]||null),t.sheenColorMap!==void 0&&(this.sheenColorMap=e[t.sheenColorMap]||null),t.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=e[t.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(t){this.name=t.name,this.blending=t.blending,this.side=t.side,this.vertexColors=t.vertexColors,this.opacity=t.opacity,this.transparent=t.transparent,this.blendSrc=t.blendSrc,this.blendDst=t.blendDst,this.blendEquation=t.blendEquation,this.blendSrcAlpha=t.blendSrcAlpha,this.blendDstAlpha=t.blendDstAlpha,this.blendEquationAlpha=t.blendEquationAlpha,this.blendColor.copy(t.blendColor),this.blendAlpha=t.blendAlpha,this.depthFunc=t.depthFunc,this.depthTest=t.depthTest,this.depthWrite=t.depthWrite,this.stencilWriteMask=t.stencilWriteMask,this.stencilFunc=t.stencilFunc,this.stencilRef=t.stencilRef,this.stencilFuncMask=t.stencilFuncMask,this.stencilFail=t.stencilFail,this.stencilZFail=t.stencilZFail,this.stencilZPass=t.stencilZPass,this.stencilWrite=t.stencilWrite;let e=t.clippingPlanes,n=null;if(e!==null){let a=e.length;n=new Array(a);for(let s=0;s!==a;++s)n[s]=e[s].clone()}return this.clippingPlanes=n,this.clipIntersection=t.clipIntersection,this.clipShadows=t.clipShadows,this.shadowSide=t.shadowSide,this.colorWrite=t.colorWrite,this.precision=t.precision,this.polygonOffset=t.polygonOffset,this.polygonOffsetFactor=t.polygonOffsetFactor,this.polygonOffsetUnits=t.polygonOffsetUnits,this.dithering=t.dithering,this.alphaTest=t.alphaTest,this.alphaHash=t.alphaHash,this.alphaToCoverage=t.alphaToCoverage,this.premultipliedAlpha=t.premultipliedAlpha,this.forceSinglePass=t.forceSinglePass,this.allowOverride=t.allowOverride,this.visible=t.visible,this.toneMapped=t.toneMapped,this.userData=JSON.parse(JSON.stringify(t.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(t){t===!0&&this.version++}},Si=new z,dh=new z,po=new z,mo=new z,Kn=class{constructor(t=new z,e=new z(0,0,-1)){this.origin=t,this.direction=e}set(t,e){return this.origin.copy(t),this.direction.copy(e),this}copy(t){return this.origin.copy(t.origin),this.direction.copy(t.direction),this}at(t,e){return e.copy(this.origin).addScaledVector(this.direction,t)}lookAt(t){return this.direction.copy(t).sub(this.origin).normalize(),this}recast(t){return this.origin.copy(this.at(t,Si)),this}closestPointToPoint(t,e){e.subVectors(t,this.origin);let n=e.dot(this.direction);return n<0?e.copy(this.origin):e.copy(this.origin).addScaledVector(this.direction,n)}distanceToPoint(t){return Math.sqrt(this.distanceSqToPoint(t))}distanceSqToPoint(t){let e=Si.subVectors(t,this.origin).dot(this.direction);return e<0?this.origin.distanceToSquared(t):(Si.copy(this.origin).addScaledVector(this.direction,e),Si.distanceToSquared(t))}distanceSqToSegment(t,e,n,a){dh.copy(t).add(e).multiplyScalar(.5),po.copy(e).sub(t).normalize(),mo.copy(this.origin).sub(dh);let s=t.distanceTo(e)*.5,r=-this.direction.dot(po),o=mo.dot(this.direction),c=-mo.dot(po),l=mo.lengthSq(),h=Math.abs(1-r*r),u,d,f,x;if(h>0)if(u=r*c-o,d=r*o-c,x=s*h,u>=0)if(d>=-x)if(d<=x){let v=1/h;u*=v,d*=v,f=u*(u+r*d+2*o)+d*(r*u+d+2*c)+l}else d=s,u=Math.max(0,-(r*d+o)),f=-u*u+d*(d+2*c)+l;else d=-s,u=Math.max(0,-(r*d+o)),f=-u*u+d*(d+2*c)+l;else d<=-x?(u=Math.max(0,-(-r*s+o)),d=u>0?-s:Math.min(Math.max(-s,-c),s),f=-u*u+d*(d+2*c)+l):d<=x?(u=0,d=Math.min(Math.max(-s,-c),s),f=d*(d+2*c)+l):(u=Math.max(0,-(r*s+o)),d=u>0?s:Math.min(Math.max(-s,-c),s),f=-u*u+d*(d+2*c)+l);else d=r>0?-s:s,u=Math.max(0,-(r*d+o)),f=-u*u+d*(d+2*c)+l;return n&&n.copy(this.origin).addScaledVector(this.direction,u),a&&a.copy(dh).addScaledVector(po,d),f}intersectSphere(t,e){if(t.radius<0)return null;Si.subVectors(t.center,this.origin);let n=Si.dot(this.direction),a=Si.dot(Si)-n*n,s=t.radius*t.radius;if(a>s)return null;let r=Math.sqrt(s-a),o=n-r,c=n+r;return c<0?null:o<0?this.at(c,e):this.at(o,e)}intersectsSphere(t){return t.radius<0?!1:this.distanceSqToPoint(t.center)<=t.radius*t.radius}distanceToPlane(t){let e=t.normal.dot(this.direction);if(e===0)return t.distanceToPoint(this.origin)===0?0:null;let n=-(this.origin.dot(t.normal)+t.constant)/e;return n>=0?n:null}intersectPlane(t,e){let n=this.distanceToPlane(t);return n===null?null:this.at(n,e)}intersectsPlane(t){let e=t.distanceToPoint(this.origin);return e===0||t.normal.dot(this.direction)*e<0}intersectBox(t,e){let n,a,s,r,o,c,l=1/this.direction.x,h=1/this.direction.y,u=1/this.direction.z,d=this.origin;return l>=0?(n=(t.min.x-d.x)*l,a=(t.max.x-d.x)*l):(n=(t.max.x-d.x)*l,a=(t.min.x-d.x)*l),h>=0?(s=(t.min.y-d.y)*h,r=(t.max.y-d.y)*h):(s=(t.max.y-d.y)*h,r=(t.min.y-d.y)*h),n>r||s>a||((s>n||isNaN(n))&&(n=s),(r<a||isNaN(a))&&(a=r),u>=0?(o=(t.min.z-d.z)*u,c=(t.max.z-d.z)*u):(o=(t.max.z-d.z)*u,c=(t.min.z-d.z)*u),n>c||o>a)||((o>n||n!==n)&&(n=o),(c<a||a!==a)&&(a=c),a<0)?null:this.at(n>=0?n:a,e)}intersectsBox(t){return this.intersectBox(t,Si)!==null}intersectTriangle(t,e,n,a,s){let r=this.origin,o=this.direction,c=o.x,l=o.y,h=o.z,u=t.x-r.x,d=t.y-r.y,f=t.z-r.z,x=e.x-r.x,v=e.y-r.y,m=e.z-r.z,g=n.x-r.x,y=n.y-r.y,w=n.z-r.z,p=Math.abs(c),_=Math.abs(l),S=Math.abs(h),b,M,E,A,I,N,L,P,U,V,O,Q;if(p>=_&&p>=S?(E=c,N=u,U=x,Q=g,c>=0?(b=l,M=h,A=d,I=f,L=v,P=m,V=y,O=w):(b=h,M=l,A=f,I=d,L=m,P=v,V=w,O=y)):_>=S?(E=l,N=d,U=v,Q=y,l>=0?(b=h,M=c,A=f,I=u,L=m,P=x,V=w,O=g):(b=c,M=h,A=u,I=f,L=x,P=m,V=g,O=w)):(E=h,N=f,U=m,Q=w,h>=0?(b=c,M=l,A=u,I=d,L=x,P=v,V=g,O=y):(b=l,M=c,A=d,I=u,L=v,P=x,V=y,O=g)),E===0)return null;let G=b/E,Z=M/E,et=1/E,ht=A-G*N,Pt=I-Z*N,Y=L-G*U,ct=P-Z*U,mt=V-G*Q,Tt=O-Z*Q,gt=mt*ct-Tt*Y,Ot=ht*Tt-Pt*mt,ge=Y*Pt-ct*ht;if(a){if(gt<0||Ot<0||ge<0)return null}else if((gt<0||Ot<0||ge<0)&&(gt>0||Ot>0||ge>0))return null;let Dt=gt+Ot+ge;if(Dt===0)return null;let kt=et*(gt*N+Ot*U+ge*Q);return(Dt>0?kt<0:kt>0)?null:this.at(kt/Dt,s)}applyMatrix4(t){return this.origin.applyMatrix4(t),this.direction.transformDirection(t),this}equals(t){return t.origin.equals(this.origin)&&t.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}},ns=class extends ri{constructor(t){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new jt(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ii,this.combine=gc,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.lightMap=t.lightMap,this.lightMapIntensity=t.lightMapIntensity,this.aoMap=t.aoMap,this.aoMapIntensity=t.aoMapIntensity,this.specularMap=t.specularMap,this.alphaMap=t.alphaMap,this.envMap=t.envMap,this.envMapRotation.copy(t.envMapRotation),this.combine=t.combine,this.reflectivity=t.reflectivity,this.refractionRatio=t.refractionRatio,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.wireframeLinecap=t.wireframeLinecap,this.wireframeLinejoin=t.wireframeLinejoin,this.fog=t.fog,this}},Lu=new oe,fa=new Kn,go=new Ge,Du=new z,bo=new z,xo=new z,yo=new z,uh=new z,_o=new z,Uu=new z,vo=new z,nn=class extends Fe{constructor(t=new Ue,e=new ns){super(),this.isMesh=!0,this.type="Mesh",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}updateMorphTargets(){let e=this.geometry.morphAttributes,n=Object.keys(e);if(n.length>0){let a=e[n[0]];if(a!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,r=a.length;s<r;s++){let o=a[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=s}}}}getVertexPosition(t,e){let n=this.geometry,a=n.attributes.position,s=n.morphAttributes.position,r=n.morphTargetsRelative;e.fromBufferAttribute(a,t);let o=this.morphTargetInfluences;if(s&&o){_o.set(0,0,0);for(let c=0,l=s.length;c<l;c++){let h=o[c],u=s[c];h!==0&&(uh.fromBufferAttribute(u,t),r?_o.addScaledVector(uh,h):_o.addScaledVector(uh.sub(e),h))}e.add(_o)}return e}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){let n=this.geometry,a=this.material,s=this.matrixWorld;a!==void 0&&(n.boundingSphere===null&&n.computeBoundingSphere(),go.copy(n.boundingSphere),go.applyMatrix4(s),fa.copy(t.ray).recast(t.near),!(go.containsPoint(fa.origin)===!1&&(fa.intersectSphere(go,Du)===null||fa.origin.distanceToSquared(Du)>(t.far-t.near)**2))&&(Lu.copy(s).invert(),fa.copy(t.ray).applyMatrix4(Lu),!(n.boundingBox!==null&&fa.intersectsBox(n.boundingBox)===!1)&&this._computeIntersections(t,e,fa)))}_computeIntersections(t,e,n){let a,s=this.geometry,r=this.material,o=s.index,c=s.attributes.position,l=s.attributes.uv,h=s.attributes.uv1,u=s.attributes.normal,d=s.groups,f=s.drawRange;if(o!==null)if(Array.isArray(r))for(let x=0,v=d.length;x<v;x++){let m=d[x],g=r[m.materialIndex],y=Math.max(m.start,f.start),w=Math.min(o.count,Math.min(m.start+m.count,f.start+f.count));for(let p=y,_=w;p<_;p+=3){let S=o.getX(p),b=o.getX(p+1),M=o.getX(p+2);a=Mo(this,g,t,n,l,h,u,S,b,M),a&&(a.faceIndex=Math.floor(p/3),a.face.materialIndex=m.materialIndex,e.push(a))}}else{let x=Math.max(0,f.start),v=Math.min(o.count,f.start+f.count);for(let m=x,g=v;m<g;m+=3){let y=o.getX(m),w=o.getX(m+1),p=o.getX(m+2);a=Mo(this,r,t,n,l,h,u,y,w,p),a&&(a.faceIndex=Math.floor(m/3),e.push(a))}}else if(c!==void 0)if(Array.isArray(r))for(let x=0,v=d.length;x<v;x++){let m=d[x],g=r[m.materialIndex],y=Math.max(m.start,f.start),w=Math.min(c.count,Math.min(m.start+m.count,f.start+f.count));for(let p=y,_=w;p<_;p+=3){let S=p,b=p+1,M=p+2;a=Mo(this,g,t,n,l,h,u,S,b,M),a&&(a.faceIndex=Math.floor(p/3),a.face.materialIndex=m.materialIndex,e.push(a))}}else{let x=Math.max(0,f.start),v=Math.min(c.count,f.start+f.count);for(let m=x,g=v;m<g;m+=3){let y=m,w=m+1,p=m+2;a=Mo(this,r,t,n,l,h,u,y,w,p),a&&(a.faceIndex=Math.floor(m/3),e.push(a))}}}};Ei=class extends wn{constructor(t=null,e=1,n=1,a,s,r,o,c,l=De,h=De,u,d){super(null,r,o,c,l,h,a,s,u,d),this.isDataTexture=!0,this.image={data:t,width:e,height:n},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}},pa=new Ge,nb=new Bt(.5,.5),So=new z,Ri=class{constructor(t=new un,e=new un,n=new un,a=new un,s=new un,r=new un){this.planes=[t,e,n,a,s,r]}set(t,e,n,a,s,r){let o=this.planes;return o[0].copy(t),o[1].copy(e),o[2].copy(n),o[3].copy(a),o[4].copy(s),o[5].copy(r),this}copy(t){let e=this.planes;for(let n=0;n<6;n++)e[n].copy(t.planes[n]);return this}setFromProjectionMatrix(t,e=Fn,n=!1){let a=this.planes,s=t.elements,r=s[0],o=s[1],c=s[2],l=s[3],h=s[4],u=s[5],d=s[6],f=s[7],x=s[8],v=s[9],m=s[10],g=s[11],y=s[12],w=s[13],p=s[14],_=s[15];if(a[0].setComponents(l-r,f-h,g-x,_-y).normalize(),a[1].setComponents(l+r,f+h,g+x,_+y).normalize(),a[2].setComponents(l+o,f+u,g+v,_+w).normalize(),a[3].setComponents(l-o,f-u,g-v,_-w).normalize(),n)a[4].setComponents(c,d,m,p).normalize(),a[5].setComponents(l-c,f-d,g-m,_-p).normalize();else if(a[4].setComponents(l-c,f-d,g-m,_-p).normalize(),e===Fn)a[5].setComponents(l+c,f+d,g+m,_+p).normalize();else if(e===Ka)a[5].setComponents(c,d,m,p).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+e);return this}intersectsObject(t){if(t.boundingSphere!==void 0)t.boundingSphere===null&&t.computeBoundingSphere(),pa.copy(t.boundingSphere).applyMatrix4(t.matrixWorld);else{let e=t.geometry;e.boundingSphere===null&&e.computeBoundingSphere(),pa.copy(e.boundingSphere).applyMatrix4(t.matrixWorld)}return this.intersectsSphere(pa)}intersectsSprite(t){pa.center.set(0,0,0);let e=nb.distanceTo(t.center);return pa.radius=.7071067811865476+e,pa.applyMatrix4(t.matrixWorld),this.intersectsSphere(pa)}intersectsSphere(t){let e=this.planes,n=t.center,a=-t.radius;for(let s=0;s<6;s++)if(e[s].distanceToPoint(n)<a)return!1;return!0}intersectsBox(t){let e=this.planes;for(let n=0;n<6;n++){let a=e[n];if(So.x=a.normal.x>0?t.max.x:t.min.x,So.y=a.normal.y>0?t.max.y:t.min.y,So.z=a.normal.z>0?t.max.z:t.min.z,a.distanceToPoint(So)<0)return!1}return!0}containsPoint(t){let e=this.planes;for(let n=0;n<6;n++)if(e[n].distanceToPoint(t)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}},Ou=new oe,ar=class i{constructor(){this.coordinateSystem=Fn,this._frustums=[],this._count=0}setFromArrayCamera(t){let e=t.cameras,n=this._frustums;for(let a=0;a<e.length;a++){let s=e[a];Ou.multiplyMatrices(s.projectionMatrix,s.matrixWorldInverse),n[a]===void 0&&(n[a]=new Ri),n[a].setFromProjectionMatrix(Ou,s.coordinateSystem,s.reversedDepth)}return this._count=e.length,this}getFrustum(t){return this._frustums[t]}intersectsObject(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsObject(t))return!0;return!1}intersectsSprite(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsSprite(t))return!0;return!1}intersectsSphere(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsSphere(t))return!0;return!1}intersectsBox(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].intersectsBox(t))return!0;return!1}containsPoint(t){let e=this._frustums;for(let n=0;n<this._count;n++)if(e[n].containsPoint(t))return!0;return!1}copy(t){this.coordinateSystem=t.coordinateSystem;let e=this._frustums,n=t._frustums;for(let a=0;a<t._count;a++)e[a]===void 0&&(e[a]=new Ri),e[a].copy(n[a]);return this._count=t._count,this}clone(){return new i().copy(this)}};Sh=class{constructor(){this.index=0,this.pool=[],this.list=[]}push(t,e,n,a){let s=this.pool,r=this.list;this.index>=s.length&&s.push({start:-1,count:-1,z:-1,index:-1});let o=s[this.index];r.push(o),this.index++,o.start=t,o.count=e,o.z=n,o.index=a}reset(){this.list.length=0,this.index=0}},Sn=new oe,sb=new jt(1,1,1),rb=new Ri,ob=new ar,wo=new Oe,ma=new Ge,ph=new z,Fu=new z,Bu=new z,cb=new z,mh=new Sh,en=new nn,Ao=[];sr=class extends nn{constructor(t,e,n=e*2,a){super(new Ue,a),this.isBatchedMesh=!0,this.perObjectFrustumCulled=!0,this.sortObjects=!0,this.boundingBox=null,this.boundingSphere=null,this.customSort=null,this._instanceInfo=[],this._geometryInfo=[],this._availableInstanceIds=[],this._availableGeometryIds=[],this._nextIndexStart=0,this._nextVertexStart=0,this._geometryCount=0,this._visibilityChanged=!0,this._geometryInitialized=!1,this._maxInstanceCount=t,this._maxVertexCount=e,this._maxIndexCount=n,this._multiDrawCounts=new Int32Array(t),this._multiDrawStarts=new Int32Array(t),this._multiDrawCount=0,this._multiDrawBytesPerElement=1,this._mergedDrawCounts=new Int32Array(t),this._mergedDrawStarts=new Int32Array(t),this._mergedDrawInstanceCounts=new Int32Array(t),this._mergedDrawCount=0,this._matricesTexture=null,this._indirectTexture=null,this._colorsTexture=null,this._previousMatricesTexture=null,this._initMatricesTexture(),this._initIndirectTexture()}get maxInstanceCount(){return this._maxInstanceCount}get instanceCount(){return this._instanceInfo.length-this._availableInstanceIds.length}get unusedVertexCount(){return this._maxVertexCount-this._nextVertexStart}get unusedIndexCount(){return this._maxIndexCount-this._nextIndexStart}_initMatricesTexture(){let t=Math.sqrt(this._maxInstanceCount*4);t=Math.ceil(t/4)*4,t=Math.max(t,4);let e=new Float32Array(t*t*4),n=new Ei(e,t,t,bn,gn);this._matricesTexture=n}_initIndirectTexture(){let t=Math.sqrt(this._maxInstanceCount);t=Math.ceil(t);let e=new Uint32Array(t*t),n=new Ei(e,t,t,Sa,An);this._indirectTexture=n}_initColorsTexture(){let t=Math.sqrt(this._maxInstanceCount);t=Math.ceil(t);let e=new Float32Array(t*t*4).fill(1),n=new Ei(e,t,t,bn,gn);n.colorSpace=Kt.workingColorSpace,this._colorsTexture=n}_initializeGeometry(t){let e=this.geometry,n=this._maxVertexCount,a=this._maxIndexCount;if(this._geometryInitialized===!1){for(let s in t.attributes){let r=t.getAttribute(s),{array:o,itemSize:c,normalized:l}=r,h=new o.constructor(n*c),u=new pn(h,c,l);e.setAttribute(s,u)}if(t.getIndex()!==null){let s=n>65535?new Uint32Array(a):new Uint16Array(a);e.setIndex(new pn(s,1))}this._geometryInitialized=!0}}_validateGeometry(t){let e=this.geometry;if(!!t.getIndex()!=!!e.getIndex())throw new Error('THREE.BatchedMesh: All geometries must consistently have "index".');for(let n in e.attributes){if(!t.hasAttribute(n))throw new Error(`THREE.BatchedMesh: Added geometry missing "${n}". All geometries must have consistent attributes.`);let a=t.getAttribute(n),s=e.getAttribute(n);if(a.itemSize!==s.itemSize||a.normalized!==s.normalized)throw new Error(`THREE.BatchedMesh: Added geometry attribute "${n}" has an inconsistent itemSize or normalized value.`)}}validateInstanceId(t){let e=this._instanceInfo;if(t<0||t>=e.length||e[t].active===!1)throw new Error(`THREE.BatchedMesh: Invalid instanceId ${t}. Instance is either out of range or has been deleted.`)}validateGeometryId(t){let e=this._geometryInfo;if(t<0||t>=e.length||e[t].active===!1)throw new Error(`THREE.BatchedMesh: Invalid geometryId ${t}. Geometry is either out of range or has been deleted.`)}setCustomSort(t){return this.customSort=t,this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Oe);let t=this.boundingBox,e=this._instanceInfo;t.makeEmpty();for(let n=0,a=e.length;n<a;n++){if(e[n].active===!1)continue;let s=e[n].geometryIndex;this.getMatrixAt(n,Sn),this.getBoundingBoxAt(s,wo).applyMatrix4(Sn),t.union(wo)}}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new Ge);let t=this.boundingSphere,e=this._instanceInfo;t.makeEmpty();for(let n=0,a=e.length;n<a;n++){if(e[n].active===!1)continue;let s=e[n].geometryIndex;this.getMatrixAt(n,Sn),this.getBoundingSphereAt(s,ma).applyMatrix4(Sn),t.union(ma)}}addInstance(t){if(this._instanceInfo.length>=this.maxInstanceCount&&this._availableInstanceIds.length===0)throw new Error("THREE.BatchedMesh: Maximum item count reached.");let n={visible:!0,active:!0,geometryIndex:t},a=null;this._availableInstanceIds.length>0?(this._availableInstanceIds.sort(fh),a=this._availableInstanceIds.shift(),this._instanceInfo[a]=n):(a=this._instanceInfo.length,this._instanceInfo.push(n));let s=this._matricesTexture;Sn.identity().toArray(s.image.data,a*16),s.needsUpdate=!0;let r=this._colorsTexture;return r&&(sb.toArray(r.image.data,a*4),r.needsUpdate=!0),this._visibilityChanged=!0,a}addGeometry(t,e=-1,n=-1){this._initializeGeometry(t),this._validateGeometry(t);let a={vertexStart:-1,vertexCount:-1,reservedVertexCount:-1,indexStart:-1,indexCount:-1,reservedIndexCount:-1,start:-1,count:-1,boundingBox:null,boundingSphere:null,active:!0},s=this._geometryInfo;a.vertexStart=this._nextVertexStart,a.reservedVertexCount=e===-1?t.getAttribute("position").count:e;let r=t.getIndex();if(r!==null&&(a.indexStart=this._nextIndexStart,a.reservedIndexCount=n===-1?r.count:n),a.indexStart!==-1&&a.indexStart+a.reservedIndexCount>this._maxIndexCount||a.vertexStart+a.reservedVertexCount>this._maxVertexCount)throw new Error("THREE.BatchedMesh: Reserved space request exceeds the maximum buffer size.");let c;return this._availableGeometryIds.length>0?(this._availableGeometryIds.sort(fh),c=this._availableGeometryIds.shift(),s[c]=a):(c=this._geometryCount,this._geometryCount++,s.push(a)),this.setGeometryAt(c,t),this._nextIndexStart=a.indexStart+a.reservedIndexCount,this._nextVertexStart=a.vertexStart+a.reservedVertexCount,c}setGeometryAt(t,e){if(t>=this._geometryCount)throw new Error("THREE.BatchedMesh: Maximum geometry count reached.");this._validateGeometry(e);let n=this.geometry,a=n.getIndex()!==null,s=n.getIndex(),r=e.getIndex(),o=this._geometryInfo[t];if(a&&r.count>o.reservedIndexCount||e.attributes.position.count>o.reservedVertexCount)throw new Error("THREE.BatchedMesh: Reserved space not large enough for provided geometry.");let c=o.vertexStart,l=o.reservedVertexCount;o.vertexCount=e.getAttribute("position").count;for(let h in n.attributes){let u=e.getAttribute(h),d=n.getAttribute(h);lb(u,d,c);let f=u.itemSize;for(let x=u.count,v=l;x<v;x++){let m=c+x;for(let g=0;g<f;g++)d.setComponent(m,g,0)}d.needsUpdate=!0,d.addUpdateRange(c*f,l*f)}if(a){let h=o.indexStart,u=o.reservedIndexCount;o.indexCount=e.getIndex().count;for(let d=0;d<r.count;d++)s.setX(h+d,c+r.getX(d));for(let d=r.count,f=u;d<f;d++)s.setX(h+d,c);s.needsUpdate=!0,s.addUpdateRange(h,o.reservedIndexCount)}return o.start=a?o.indexStart:o.vertexStart,o.count=a?o.indexCount:o.vertexCount,o.boundingBox=null,e.boundingBox!==null&&(o.boundingBox=e.boundingBox.clone()),o.boundingSphere=null,e.boundingSphere!==null&&(o.boundingSphere=e.boundingSphere.clone()),this._visibilityChanged=!0,t}deleteGeometry(t){let e=this._geometryInfo;if(t>=e.length||e[t].active===!1)return this;let n=this._instanceInfo;for(let a=0,s=n.length;a<s;a++)n[a].active&&n[a].geometryIndex===t&&this.deleteInstance(a);return e[t].active=!1,this._availableGeometryIds.push(t),this._visibilityChanged=!0,this}deleteInstance(t){return this.validateInstanceId(t),this._instanceInfo[t].active=!1,this._availableInstanceIds.push(t),this._visibilityChanged=!0,this}optimize(){let t=0,e=0,n=this._geometryInfo,a=n.map((r,o)=>o).sort((r,o)=>n[r].vertexStart-n[o].vertexStart),s=this.geometry;for(let r=0,o=n.length;r<o;r++){let c=a[r],l=n[c];if(l.active!==!1){if(s.index!==null){if(l.indexStart!==e){let{indexStart:h,vertexStart:u,reservedIndexCount:d}=l,f=s.index,x=f.array,v=t-u;for(let m=h;m<h+d;m++)x[m]=x[m]+v;f.array.copyWithin(e,h,h+d),f.addUpdateRange(e,d),f.needsUpdate=!0,l.indexStart=e}e+=l.reservedIndexCount}if(l.vertexStart!==t){let{vertexStart:h,reservedVertexCount:u}=l,d=s.attributes;for(let f in d){let x=d[f],{array:v,itemSize:m}=x;v.copyWithin(t*m,h*m,(h+u)*m),x.addUpdateRange(t*m,u*m),x.needsUpdate=!0}l.vertexStart=t}t+=l.reservedVertexCount,l.start=s.index?l.indexStart:l.vertexStart}}return this._nextIndexStart=e,this._nextVertexStart=t,this._visibilityChanged=!0,this}getBoundingBoxAt(t,e){if(t>=this._geometryCount)return null;let n=this.geometry,a=this._geometryInfo[t];if(a.boundingBox===null){let s=new Oe,r=n.index,o=n.attributes.position;for(let c=a.start,l=a.start+a.count;c<l;c++){let h=c;r&&(h=r.getX(h)),s.expandByPoint(ph.fromBufferAttribute(o,h))}a.boundingBox=s}return e.copy(a.boundingBox),e}getBoundingSphereAt(t,e){if(t>=this._geometryCount)return null;let n=this.geometry,a=this._geometryInfo[t];if(a.boundingSphere===null){let s=new Ge;this.getBoundingBoxAt(t,wo),wo.getCenter(s.center);let r=n.index,o=n.attributes.position,c=0;for(let l=a.start,h=a.start+a.count;l<h;l++){let u=l;r&&(u=r.getX(u)),ph.fromBufferAttribute(o,u),c=Math.max(c,s.center.distanceToSquared(ph))}s.radius=Math.sqrt(c),a.boundingSphere=s}return e.copy(a.boundingSphere),e}setMatrixAt(t,e){this.validateInstanceId(t);let n=this._matricesTexture,a=this._matricesTexture.image.data;return e.toArray(a,t*16),n.needsUpdate=!0,this}getMatrixAt(t,e){return this.validateInstanceId(t),e.fromArray(this._matricesTexture.image.data,t*16)}setColorAt(t,e){return this.validateInstanceId(t),this._colorsTexture===null&&this._initColorsTexture(),e.toArray(this._colorsTexture.image.data,t*4),this._colorsTexture.needsUpdate=!0,this}getColorAt(t,e){return this.validateInstanceId(t),this._colorsTexture===null?e.isVector4?e.set(1,1,1,1):e.setRGB(1,1,1):e.fromArray(this._colorsTexture.image.data,t*4)}setVisibleAt(t,e){return this.validateInstanceId(t),this._instanceInfo[t].visible===e?this:(this._instanceInfo[t].visible=e,this._visibilityChanged=!0,this)}getVisibleAt(t){return this.validateInstanceId(t),this._instanceInfo[t].visible}setGeometryIdAt(t,e){return this.validateInstanceId(t),this.validateGeometryId(e),this._instanceInfo[t].geometryIndex=e,this._visibilityChanged=!0,this}getGeometryIdAt(t){return this.validateInstanceId(t),this._instanceInfo[t].geometryIndex}getGeometryRangeAt(t,e={}){this.validateGeometryId(t);let n=this._geometryInfo[t];return e.vertexStart=n.vertexStart,e.vertexCount=n.vertexCount,e.reservedVertexCount=n.reservedVertexCount,e.indexStart=n.indexStart,e.indexCount=n.indexCount,e.reservedIndexCount=n.reservedIndexCount,e.start=n.start,e.count=n.count,e}setInstanceCount(t){let e=this._availableInstanceIds,n=this._instanceInfo;for(e.sort(fh);e[e.length-1]===n.length-1;)n.pop(),e.pop();if(t<n.length)throw new Error(`THREE.BatchedMesh: Instance ids outside the range ${t} are being used. Cannot shrink instance count.`);let a=new Int32Array(t),s=new Int32Array(t);ni(this._multiDrawCounts,a),ni(this._multiDrawStarts,s),this._multiDrawCounts=a,this._multiDrawStarts=s;let r=new Int32Array(t),o=new Int32Array(t),c=new Int32Array(t);ni(this._mergedDrawCounts,r),ni(this._mergedDrawStarts,o),ni(this._mergedDrawInstanceCounts,c),this._mergedDrawCounts=r,this._mergedDrawStarts=o,this._mergedDrawInstanceCounts=c,this._maxInstanceCount=t;let l=this._indirectTexture,h=this._matricesTexture,u=this._colorsTexture;l.dispose(),this._initIndirectTexture(),ni(l.image.data,this._indirectTexture.image.data),h.dispose(),this._initMatricesTexture(),ni(h.image.data,this._matricesTexture.image.data),u&&(u.dispose(),this._initColorsTexture(),ni(u.image.data,this._colorsTexture.image.data)),this._previousMatricesTexture!==null&&(this._previousMatricesTexture.dispose(),this._previousMatricesTexture=null)}setGeometrySize(t,e){let n=[...this._geometryInfo].filter(o=>o.active);if(Math.max(...n.map(o=>o.vertexStart+o.reservedVertexCount))>t)throw new Error(`THREE.BatchedMesh: Geometry vertex values are being used outside the range ${t}. Cannot shrink further.`);if(this.geometry.index&&Math.max(...n.map(c=>c.indexStart+c.reservedIndexCount))>e)throw new Error(`THREE.BatchedMesh: Geometry index values are being used outside the range ${e}. Cannot shrink further.`);let s=this.geometry;s.dispose(),this._maxVertexCount=t,this._maxIndexCount=e,this._geometryInitialized&&(this._geometryInitialized=!1,this.geometry=new Ue,this._initializeGeometry(s));let r=this.geometry;s.index&&ni(s.index.array,r.index.array);for(let o in s.attributes)ni(s.attributes[o].array,r.attributes[o].array);this._visibilityChanged=!0}raycast(t,e){let n=this._instanceInfo,a=this._geometryInfo,s=this.matrixWorld,r=this.geometry;en.material=this.material,en.geometry.index=r.index,en.geometry.attributes=r.attributes,en.geometry.boundingBox===null&&(en.geometry.boundingBox=new Oe),en.geometry.boundingSphere===null&&(en.geometry.boundingSphere=new Ge);for(let o=0,c=n.length;o<c;o++){if(!n[o].visible||!n[o].active)continue;let l=n[o].geometryIndex,h=a[l];en.geometry.setDrawRange(h.start,h.count),this.getMatrixAt(o,en.matrixWorld).premultiply(s),this.getBoundingBoxAt(l,en.geometry.boundingBox),this.getBoundingSphereAt(l,en.geometry.boundingSphere),en.raycast(t,Ao);for(let u=0,d=Ao.length;u<d;u++){let f=Ao[u];f.object=this,f.batchId=o,e.push(f)}Ao.length=0}en.material=null,en.geometry.index=null,en.geometry.attributes={},en.geometry.setDrawRange(0,1/0)}copy(t){return super.copy(t),this.geometry=t.geometry.clone(),this.perObjectFrustumCulled=t.perObjectFrustumCulled,this.sortObjects=t.sortObjects,this.boundingBox=t.boundingBox!==null?t.boundingBox.clone():null,this.boundingSphere=t.boundingSphere!==null?t.boundingSphere.clone():null,this._geometryInfo=t._geometryInfo.map(e=>({...e,boundingBox:e.boundingBox!==null?e.boundingBox.clone():null,boundingSphere:e.boundingSphere!==null?e.boundingSphere.clone():null})),this._instanceInfo=t._instanceInfo.map(e=>({...e})),this._availableInstanceIds=t._availableInstanceIds.slice(),this._availableGeometryIds=t._availableGeometryIds.slice(),this._nextIndexStart=t._nextIndexStart,this._nextVertexStart=t._nextVertexStart,this._geometryCount=t._geometryCount,this._maxInstanceCount=t._maxInstanceCount,this._maxVertexCount=t._maxVertexCount,this._maxIndexCount=t._maxIndexCount,this._geometryInitialized=t._geometryInitialized,this._multiDrawCounts=t._multiDrawCounts.slice(),this._multiDrawStarts=t._multiDrawStarts.slice(),this._multiDrawBytesPerElement=t._multiDrawBytesPerElement,this._mergedDrawCounts=t._mergedDrawCounts.slice(),this._mergedDrawStarts=t._mergedDrawStarts.slice(),this._mergedDrawInstanceCounts=t._mergedDrawInstanceCounts.slice(),this._indirectTexture=t._indirectTexture.clone(),this._indirectTexture.image.data=this._indirectTexture.image.data.slice(),this._matricesTexture=t._matricesTexture.clone(),this._matricesTexture.image.data=this._matricesTexture.image.data.slice(),t._colorsTexture!==null?(this._colorsTexture=t._colorsTexture.clone(),this._colorsTexture.image.data=this._colorsTexture.image.data.slice()):this._colorsTexture=null,this}dispose(){super.dispose(),this.geometry.dispose(),this._matricesTexture.dispose(),this._matricesTexture=null,this._indirectTexture.dispose(),this._indirectTexture=null,this._colorsTexture!==null&&(this._colorsTexture.dispose(),this._colorsTexture=null),this._previousMatricesTexture!==null&&(this._previousMatricesTexture.dispose(),this._previousMatricesTexture=null)}_updateDrawParameters(t,e,n,a="multiDraw"){if(!this._visibilityChanged&&!this.perObjectFrustumCulled&&!this.sortObjects)return;let s=e.getIndex(),r=s===null?1:s.array.BYTES_PER_ELEMENT,o=1;n.wireframe&&(o=2,r=e.attributes.position.count>65535?4:2);let c=this._instanceInfo,l=this._multiDrawStarts,h=this._multiDrawCounts,u=this._mergedDrawStarts,d=this._mergedDrawCounts,f=this._mergedDrawInstanceCounts,x=this._geometryInfo,v=this.perObjectFrustumCulled,m=this._indirectTexture,g=m.image.data,y=t.isArrayCamera?ob:rb;v&&(t.isArrayCamera?y.setFromArrayCamera(t):(Sn.multiplyMatrices(t.projectionMatrix,t.matrixWorldInverse).multiply(this.matrixWorld),y.setFromProjectionMatrix(Sn,t.coordinateSystem,t.reversedDepth)));let w=0,p=0;if(this.sortObjects){Sn.copy(this.matrixWorld).invert(),Fu.setFromMatrixPosition(t.matrixWorld).applyMatrix4(Sn),Bu.set(0,0,-1).transformDirection(t.matrixWorld).transformDirection(Sn);for(let b=0,M=c.length;b<M;b++)if(c[b].visible&&c[b].active){let E=c[b].geometryIndex;this.getMatrixAt(b,Sn),this.getBoundingSphereAt(E,ma).applyMatrix4(Sn);let A=!1;if(v&&(A=!y.intersectsSphere(ma)),!A){let I=x[E],N=cb.subVectors(ma.center,Fu).dot(Bu);mh.push(I.start,I.count,N,b)}}let _=mh.list,S=this.customSort;S===null?_.sort(n.transparent?ab:ib):S.call(this,_,t);for(let b=0,M=_.length;b<M;b++){let E=_[b],A=E.start*r*o,I=E.count*o;a==="merged"?p>0&&u[p-1]===A&&d[p-1]===I?f[p-1]++:(u[p]=A,d[p]=I,f[p]=1,p++):(l[w]=A,h[w]=I),g[w]=E.index,w++}mh.reset()}else for(let _=0,S=c.length;_<S;_++)if(c[_].visible&&c[_].active){let b=c[_].geometryIndex,M=!1;if(v&&(this.getMatrixAt(_,Sn),this.getBoundingSphereAt(b,ma).applyMatrix4(Sn),M=!y.intersectsSphere(ma)),!M){let E=x[b],A=E.start*r*o,I=E.count*o;a==="merged"?p>0&&u[p-1]===A&&d[p-1]===I?f[p-1]++:(u[p]=A,d[p]=I,f[p]=1,p++):(l[w]=A,h[w]=I),g[w]=_,w++}}m.needsUpdate=!0,this._multiDrawCount=w,this._mergedDrawCount=p,this._multiDrawBytesPerElement=r,this._visibilityChanged=!1}onBeforeRender(t,e,n,a,s){t.isWebGPURenderer===!0?(this._visibilityChanged||this.perObjectFrustumCulled||this.sortObjects)&&(this._indirectTexture.needsUpdate=!0):this._updateDrawParameters(n,a,s)}onBeforeShadow(t,e,n,a,s,r){t.isWebGPURenderer!==!0&&this._updateDrawParameters(a,s,r)}},ga=class extends ri{constructor(t){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new jt(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.linewidth=t.linewidth,this.linecap=t.linecap,this.linejoin=t.linejoin,this.fog=t.fog,this}},Ko=new z,Zo=new z,ku=new oe,js=new Kn,Eo=new Ge,gh=new z,zu=new z,ba=class extends Fe{constructor(t=new Ue,e=new ga){super(),this.isLine=!0,this.type="Line",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}computeLineDistances(){let t=this.geometry;if(t.index===null){let e=t.attributes.position,n=[0];for(let a=1,s=e.count;a<s;a++)Ko.fromBufferAttribute(e,a-1),Zo.fromBufferAttribute(e,a),n[a]=n[a-1],n[a]+=Ko.distanceTo(Zo);t.setAttribute("lineDistance",new xe(n,1))}else Ft("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){let n=this.geometry,a=this.matrixWorld,s=t.params.Line.threshold,r=n.drawRange;if(n.boundingSphere===null&&n.computeBoundingSphere(),Eo.copy(n.boundingSphere),Eo.applyMatrix4(a),Eo.radius+=s,t.ray.intersectsSphere(Eo)===!1)return;ku.copy(a).invert(),js.copy(t.ray).applyMatrix4(ku);let o=s/((this.scale.x+this.scale.y+this.scale.z)/3),c=o*o,l=this.isLineSegments?2:1,h=n.index,d=n.attributes.position;if(h!==null){let f=Math.max(0,r.start),x=Math.min(h.count,r.start+r.count);for(let v=f,m=x-1;v<m;v+=l){let g=h.getX(v),y=h.getX(v+1),w=To(this,t,js,c,g,y,v);w&&e.push(w)}if(this.isLineLoop){let v=h.getX(x-1),m=h.getX(f),g=To(this,t,js,c,v,m,x-1);g&&e.push(g)}}else{let f=Math.max(0,r.start),x=Math.min(d.count,r.start+r.count);for(let v=f,m=x-1;v<m;v+=l){let g=To(this,t,js,c,v,v+1,v);g&&e.push(g)}if(this.isLineLoop){let v=To(this,t,js,c,x-1,f,x-1);v&&e.push(v)}}}updateMorphTargets(){let e=this.geometry.morphAttributes,n=Object.keys(e);if(n.length>0){let a=e[n[0]];if(a!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,r=a.length;s<r;s++){let o=a[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=s}}}}};Vu=new z,Hu=new z,is=class extends ba{constructor(t,e){super(t,e),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){let t=this.geometry;if(t.index===null){let e=t.attributes.position,n=[];for(let a=0,s=e.count;a<s;a+=2)Vu.fromBufferAttribute(e,a),Hu.fromBufferAttribute(e,a+1),n[a]=a===0?0:n[a-1],n[a+1]=n[a]+Vu.distanceTo(Hu);t.setAttribute("lineDistance",new xe(n,1))}else Ft("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}},rr=class extends ba{constructor(t,e){super(t,e),this.isLineLoop=!0,this.type="LineLoop"}},Qo=class extends ri{constructor(t){super(),this.isPointsMaterial=!0,this.type="PointsMaterial",this.color=new jt(16777215),this.map=null,this.alphaMap=null,this.size=1,this.sizeAttenuation=!0,this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.alphaMap=t.alphaMap,this.size=t.size,this.sizeAttenuation=t.sizeAttenuation,this.fog=t.fog,this}},Gu=new oe,wh=new Kn,Io=new Ge,Ro=new z,or=class extends Fe{constructor(t=new Ue,e=new Qo){super(),this.isPoints=!0,this.type="Points",this.geometry=t,this.material=e,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(t,e){return super.copy(t,e),t.morphTargetInfluences!==void 0?this.morphTargetInfluences=t.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,t.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},t.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(t.material)?t.material.slice():t.material,this.geometry=t.geometry,this}intersectsFrustum(t){return t.intersectsObject(this)}raycast(t,e){let n=this.geometry,a=this.matrixWorld,s=t.params.Points.threshold,r=n.drawRange;if(n.boundingSphere===null&&n.computeBoundingSphere(),Io.copy(n.boundingSphere),Io.applyMatrix4(a),Io.radius+=s,t.ray.intersectsSphere(Io)===!1)return;Gu.copy(a).invert(),wh.copy(t.ray).applyMatrix4(Gu);let o=s/((this.scale.x+this.scale.y+this.scale.z)/3),c=o*o,l=n.index,u=n.attributes.position;if(l!==null){let d=Math.max(0,r.start),f=Math.min(l.count,r.start+r.count);for(let x=d,v=f;x<v;x++){let m=l.getX(x);Ro.fromBufferAttribute(u,m),Wu(Ro,m,c,a,t,e,this)}}else{let d=Math.max(0,r.start),f=Math.min(u.count,r.start+r.count);for(let x=d,v=f;x<v;x++)Ro.fromBufferAttribute(u,x),Wu(Ro,x,c,a,t,e,this)}}updateMorphTargets(){let e=this.geometry.morphAttributes,n=Object.keys(e);if(n.length>0){let a=e[n[0]];if(a!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let s=0,r=a.length;s<r;s++){let o=a[s].name||String(s);this.morphTargetInfluences.push(0),this.morphTargetDictionary[o]=s}}}}};cr=class extends wn{constructor(t=[],e=va,n,a,s,r,o,c,l,h){super(t,e,n,a,s,r,o,c,l,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(t){this.image=t}},Ci=class extends wn{constructor(t,e,n=An,a,s,r,o=De,c=De,l,h=Ti,u=1){if(h!==Ti&&h!==Pi)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");let d={width:t,height:e,depth:u};super(d,a,s,r,o,c,h,n,l),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(t){return super.copy(t),this.source=new $a(Object.assign({},t.image)),this.compareFunction=t.compareFunction,this}toJSON(t){let e=super.toJSON(t);return e.compareFunction=this.compareFunction,e}},lr=class extends Ci{constructor(t,e=An,n=va,a,s,r=De,o=De,c,l=Ti){let h={width:t,height:t,depth:1},u=[h,h,h,h,h,h];super(t,t,e,n,a,s,r,o,c,l),this.image=u,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(t){this.image=t}},hr=class extends wn{constructor(t=null){super(),this.sourceTexture=t,this.isExternalTexture=!0}copy(t){return super.copy(t),this.sourceTexture=t.sourceTexture,this}},as=class i extends Ue{constructor(t=1,e=1,n=1,a=1,s=1,r=1){super(),this.type="BoxGeometry",this.parameters={width:t,height:e,depth:n,widthSegments:a,heightSegments:s,depthSegments:r};let o=this;a=Math.floor(a),s=Math.floor(s),r=Math.floor(r);let c=[],l=[],h=[],u=[],d=0,f=0;x("z","y","x",-1,-1,n,e,t,r,s,0),x("z","y","x",1,-1,n,e,-t,r,s,1),x("x","z","y",1,1,t,n,e,a,r,2),x("x","z","y",1,-1,t,n,-e,a,r,3),x("x","y","z",1,-1,t,e,n,a,s,4),x("x","y","z",-1,-1,t,e,-n,a,s,5),this.setIndex(c),this.setAttribute("position",new xe(l,3)),this.setAttribute("normal",new xe(h,3)),this.setAttribute("uv",new xe(u,2));function x(v,m,g,y,w,p,_,S,b,M,E){let A=p/b,I=_/M,N=p/2,L=_/2,P=S/2,U=b+1,V=M+1,O=0,Q=0,G=new z;for(let Z=0;Z<V;Z++){let et=Z*I-L;for(let ht=0;ht<U;ht++){let Pt=ht*A-N;G[v]=Pt*y,G[m]=et*w,G[g]=P,l.push(G.x,G.y,G.z),G[v]=0,G[m]=0,G[g]=S>0?1:-1,h.push(G.x,G.y,G.z),u.push(ht/b),u.push(1-Z/M),O+=1}}for(let Z=0;Z<M;Z++)for(let et=0;et<b;et++){let ht=d+et+U*Z,Pt=d+et+U*(Z+1),Y=d+(et+1)+U*(Z+1),ct=d+(et+1)+U*Z;c.push(ht,Pt,ct),c.push(Pt,Y,ct),Q+=6}o.addGroup(f,Q,E),f+=Q,d+=O}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.width,t.height,t.depth,t.widthSegments,t.heightSegments,t.depthSegments)}},ss=class i extends Ue{constructor(t=1,e=1,n=1,a=32,s=1,r=!1,o=0,c=Math.PI*2){super(),this.type="CylinderGeometry",this.parameters={radiusTop:t,radiusBottom:e,height:n,radialSegments:a,heightSegments:s,openEnded:r,thetaStart:o,thetaLength:c};let l=this;a=Math.floor(a),s=Math.floor(s);let h=[],u=[],d=[],f=[],x=0,v=[],m=n/2,g=0;y(),r===!1&&(t>0&&w(!0),e>0&&w(!1)),this.setIndex(h),this.setAttribute("position",new xe(u,3)),this.setAttribute("normal",new xe(d,3)),this.setAttribute("uv",new xe(f,2));function y(){let p=new z,_=new z,S=0,b=(e-t)/n;for(let M=0;M<=s;M++){let E=[],A=M/s,I=A*(e-t)+t;for(let N=0;N<=a;N++){let L=N/a,P=L*c+o,U=Math.sin(P),V=Math.cos(P);_.x=I*U,_.y=-A*n+m,_.z=I*V,u.push(_.x,_.y,_.z),p.set(U,b,V).normalize(),d.push(p.x,p.y,p.z),f.push(L,1-A),E.push(x++)}v.push(E)}for(let M=0;M<a;M++)for(let E=0;E<s;E++){let A=v[E][M],I=v[E+1][M],N=v[E+1][M+1],L=v[E][M+1];(t>0||E!==0)&&(h.push(A,I,L),S+=3),(e>0||E!==s-1)&&(h.push(I,N,L),S+=3)}l.addGroup(g,S,0),g+=S}function w(p){let _=x,S=new Bt,b=new z,M=0,E=p===!0?t:e,A=p===!0?1:-1;for(let N=1;N<=a;N++)u.push(0,m*A,0),d.push(0,A,0),f.push(.5,.5),x++;let I=x;for(let N=0;N<=a;N++){let P=N/a*c+o,U=Math.cos(P),V=Math.sin(P);b.x=E*V,b.y=m*A,b.z=E*U,u.push(b.x,b.y,b.z),d.push(0,A,0),S.x=U*.5+.5,S.y=V*.5*A+.5,f.push(S.x,S.y),x++}for(let N=0;N<a;N++){let L=_+N,P=I+N;p===!0?h.push(P,P+1,L):h.push(P+1,P,L),M+=3}l.addGroup(g,M,p===!0?1:2),g+=M}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.radiusTop,t.radiusBottom,t.height,t.radialSegments,t.heightSegments,t.openEnded,t.thetaStart,t.thetaLength)}},dr=class i extends ss{constructor(t=1,e=1,n=32,a=1,s=!1,r=0,o=Math.PI*2){super(0,t,e,n,a,s,r,o),this.type="ConeGeometry",this.parameters={radius:t,height:e,radialSegments:n,heightSegments:a,openEnded:s,thetaStart:r,thetaLength:o}}static fromJSON(t){return new i(t.radius,t.height,t.radialSegments,t.heightSegments,t.openEnded,t.thetaStart,t.thetaLength)}},ur=class i extends Ue{constructor(t=1,e=1,n=1,a=1){super(),this.type="PlaneGeometry",this.parameters={width:t,height:e,widthSegments:n,heightSegments:a};let s=t/2,r=e/2,o=Math.floor(n),c=Math.floor(a),l=o+1,h=c+1,u=t/o,d=e/c,f=[],x=[],v=[],m=[];for(let g=0;g<h;g++){let y=g*d-r;for(let w=0;w<l;w++){let p=w*u-s;x.push(p,-y,0),v.push(0,0,1),m.push(w/o),m.push(1-g/c)}}for(let g=0;g<c;g++)for(let y=0;y<o;y++){let w=y+l*g,p=y+l*(g+1),_=y+1+l*(g+1),S=y+1+l*g;f.push(w,p,S),f.push(p,_,S)}this.setIndex(f),this.setAttribute("position",new xe(x,3)),this.setAttribute("normal",new xe(v,3)),this.setAttribute("uv",new xe(m,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.width,t.height,t.widthSegments,t.heightSegments)}},fr=class i extends Ue{constructor(t=1,e=32,n=16,a=0,s=Math.PI*2,r=0,o=Math.PI){super(),this.type="SphereGeometry",this.parameters={radius:t,widthSegments:e,heightSegments:n,phiStart:a,phiLength:s,thetaStart:r,thetaLength:o},e=Math.max(3,Math.floor(e)),n=Math.max(2,Math.floor(n));let c=Math.min(r+o,Math.PI),l=0,h=[],u=new z,d=new z,f=[],x=[],v=[],m=[];for(let g=0;g<=n;g++){let y=[],w=g/n,p=r+w*o,_=t*Math.cos(p),S=Math.sqrt(t*t-_*_),b=0;g===0&&r===0?b=.5/e:g===n&&c===Math.PI&&(b=-.5/e);for(let M=0;M<=e;M++){let E=M/e,A=a+E*s;u.x=-S*Math.cos(A),u.y=_,u.z=S*Math.sin(A),x.push(u.x,u.y,u.z),d.copy(u).normalize(),v.push(d.x,d.y,d.z),m.push(E+b,1-w),y.push(l++)}h.push(y)}for(let g=0;g<n;g++)for(let y=0;y<e;y++){let w=h[g][y+1],p=h[g][y],_=h[g+1][y],S=h[g+1][y+1];(g!==0||r>0)&&f.push(w,p,S),(g!==n-1||c<Math.PI)&&f.push(p,_,S)}this.setIndex(f),this.setAttribute("position",new xe(x,3)),this.setAttribute("normal",new xe(v,3)),this.setAttribute("uv",new xe(m,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.radius,t.widthSegments,t.heightSegments,t.phiStart,t.phiLength,t.thetaStart,t.thetaLength)}},pr=class i extends Ue{constructor(t=1,e=.4,n=12,a=48,s=Math.PI*2,r=0,o=Math.PI*2){super(),this.type="TorusGeometry",this.parameters={radius:t,tube:e,radialSegments:n,tubularSegments:a,arc:s,thetaStart:r,thetaLength:o},n=Math.floor(n),a=Math.floor(a);let c=[],l=[],h=[],u=[],d=new z,f=new z,x=new z;for(let v=0;v<=n;v++){let m=r+v/n*o;for(let g=0;g<=a;g++){let y=g/a*s;f.x=(t+e*Math.cos(m))*Math.cos(y),f.y=(t+e*Math.cos(m))*Math.sin(y),f.z=e*Math.sin(m),l.push(f.x,f.y,f.z),d.x=t*Math.cos(y),d.y=t*Math.sin(y),x.subVectors(f,d).normalize(),h.push(x.x,x.y,x.z),u.push(g/a),u.push(v/n)}}for(let v=1;v<=n;v++)for(let m=1;m<=a;m++){let g=(a+1)*v+m-1,y=(a+1)*(v-1)+m-1,w=(a+1)*(v-1)+m,p=(a+1)*v+m;c.push(g,y,p),c.push(y,w,p)}this.setIndex(c),this.setAttribute("position",new xe(l,3)),this.setAttribute("normal",new xe(h,3)),this.setAttribute("uv",new xe(u,2))}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}static fromJSON(t){return new i(t.radius,t.tube,t.radialSegments,t.tubularSegments,t.arc,t.thetaStart,t.thetaLength)}},mr=class extends Ue{constructor(t=null){if(super(),this.type="WireframeGeometry",this.parameters={geometry:t},t!==null){let e=[],n=new Set,a=new z,s=new z;if(t.index!==null){let r=t.attributes.position,o=t.index,c=t.groups;c.length===0&&(c=[{start:0,count:o.count,materialIndex:0}]);for(let l=0,h=c.length;l<h;++l){let u=c[l],d=u.start,f=u.count;for(let x=d,v=d+f;x<v;x+=3)for(let m=0;m<3;m++){let g=o.getX(x+m),y=o.getX(x+(m+1)%3);a.fromBufferAttribute(r,g),s.fromBufferAttribute(r,y),ju(a,s,n)===!0&&(e.push(a.x,a.y,a.z),e.push(s.x,s.y,s.z))}}}else{let r=t.attributes.position;for(let o=0,c=r.count/3;o<c;o++)for(let l=0;l<3;l++){let h=3*o+l,u=3*o+(l+1)%3;a.fromBufferAttribute(r,h),s.fromBufferAttribute(r,u),ju(a,s,n)===!0&&(e.push(a.x,a.y,a.z),e.push(s.x,s.y,s.z))}}this.setAttribute("position",new xe(e,3))}}copy(t){return super.copy(t),this.parameters=Object.assign({},t.parameters),this}};Br={clone:Aa,merge:sn},db=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,ub=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`,Bn=class extends ri{constructor(t){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=db,this.fragmentShader=ub,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,t!==void 0&&this.setValues(t)}copy(t){return super.copy(t),this.fragmentShader=t.fragmentShader,this.vertexShader=t.vertexShader,this.uniforms=Aa(t.uniforms),this.uniformsGroups=hb(t.uniformsGroups),this.defines=Object.assign({},t.defines),this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.fog=t.fog,this.lights=t.lights,this.clipping=t.clipping,this.extensions=Object.assign({},t.extensions),this.glslVersion=t.glslVersion,this.defaultAttributeValues=Object.assign({},t.defaultAttributeValues),this.index0AttributeName=t.index0AttributeName,this.uniformsNeedUpdate=t.uniformsNeedUpdate,this}toJSON(t){let e=super.toJSON(t);e.glslVersion=this.glslVersion,e.uniforms={};for(let a in this.uniforms){let r=this.uniforms[a].value;r&&r.isTexture?e.uniforms[a]={type:"t",value:r.toJSON(t).uuid}:r&&r.isColor?e.uniforms[a]={type:"c",value:r.getHex()}:r&&r.isVector2?e.uniforms[a]={type:"v2",value:r.toArray()}:r&&r.isVector3?e.uniforms[a]={type:"v3",value:r.toArray()}:r&&r.isVector4?e.uniforms[a]={type:"v4",value:r.toArray()}:r&&r.isMatrix3?e.uniforms[a]={type:"m3",value:r.toArray()}:r&&r.isMatrix4?e.uniforms[a]={type:"m4",value:r.toArray()}:e.uniforms[a]={value:r}}Object.keys(this.defines).length>0&&(e.defines=this.defines),e.vertexShader=this.vertexShader,e.fragmentShader=this.fragmentShader,e.lights=this.lights,e.clipping=this.clipping;let n={};for(let a in this.extensions)this.extensions[a]===!0&&(n[a]=!0);return Object.keys(n).length>0&&(e.extensions=n),e}fromJSON(t,e){if(super.fromJSON(t,e),t.uniforms!==void 0)for(let n in t.uniforms){let a=t.uniforms[n];switch(this.uniforms[n]={},a.type){case"t":this.uniforms[n].value=e[a.value]||null;break;case"c":this.uniforms[n].value=new jt().setHex(a.value);break;case"v2":this.uniforms[n].value=new Bt().fromArray(a.value);break;case"v3":this.uniforms[n].value=new z().fromArray(a.value);break;case"v4":this.uniforms[n].value=new ce().fromArray(a.value);break;case"m3":this.uniforms[n].value=new Vt().fromArray(a.value);break;case"m4":this.uniforms[n].value=new oe().fromArray(a.value);break;default:this.uniforms[n].value=a.value}}if(t.defines!==void 0&&(this.defines=t.defines),t.vertexShader!==void 0&&(this.vertexShader=t.vertexShader),t.fragmentShader!==void 0&&(this.fragmentShader=t.fragmentShader),t.glslVersion!==void 0&&(this.glslVersion=t.glslVersion),t.extensions!==void 0)for(let n in t.extensions)this.extensions[n]=t.extensions[n];return t.lights!==void 0&&(this.lights=t.lights),t.clipping!==void 0&&(this.clipping=t.clipping),this}},$o=class extends Bn{constructor(t){super(t),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}},gr=class extends ri{constructor(t){super(),this.isMeshLambertMaterial=!0,this.type="MeshLambertMaterial",this.color=new jt(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.emissive=new jt(0),this.emissiveIntensity=1,this.emissiveMap=null,this.bumpMap=null,this.bumpScale=1,this.normalMap=null,this.normalMapType=Qc,this.normalScale=new Bt(1,1),this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ii,this.combine=gc,this.reflectivity=1,this.envMapIntensity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.flatShading=!1,this.fog=!0,this.setValues(t)}copy(t){return super.copy(t),this.color.copy(t.color),this.map=t.map,this.lightMap=t.lightMap,this.lightMapIntensity=t.lightMapIntensity,this.aoMap=t.aoMap,this.aoMapIntensity=t.aoMapIntensity,this.emissive.copy(t.emissive),this.emissiveMap=t.emissiveMap,this.emissiveIntensity=t.emissiveIntensity,this.bumpMap=t.bumpMap,this.bumpScale=t.bumpScale,this.normalMap=t.normalMap,this.normalMapType=t.normalMapType,this.normalScale.copy(t.normalScale),this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this.specularMap=t.specularMap,this.alphaMap=t.alphaMap,this.envMap=t.envMap,this.envMapRotation.copy(t.envMapRotation),this.combine=t.combine,this.reflectivity=t.reflectivity,this.envMapIntensity=t.envMapIntensity,this.refractionRatio=t.refractionRatio,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this.wireframeLinecap=t.wireframeLinecap,this.wireframeLinejoin=t.wireframeLinejoin,this.flatShading=t.flatShading,this.fog=t.fog,this}},tc=class extends ri{constructor(t){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=Tf,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(t)}copy(t){return super.copy(t),this.depthPacking=t.depthPacking,this.map=t.map,this.alphaMap=t.alphaMap,this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this.wireframe=t.wireframe,this.wireframeLinewidth=t.wireframeLinewidth,this}},ec=class extends ri{constructor(t){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(t)}copy(t){return super.copy(t),this.map=t.map,this.alphaMap=t.alphaMap,this.displacementMap=t.displacementMap,this.displacementScale=t.displacementScale,this.displacementBias=t.displacementBias,this}};Gi=class{constructor(t,e,n,a){this.parameterPositions=t,this._cachedIndex=0,this.resultBuffer=a!==void 0?a:new e.constructor(n),this.sampleValues=e,this.valueSize=n,this.settings=null,this.DefaultSettings_={}}evaluate(t){let e=this.parameterPositions,n=this._cachedIndex,a=e[n],s=e[n-1];n:{t:{let r;e:{i:if(!(t<a)){for(let o=n+2;;){if(a===void 0){if(t<s)break i;return n=e.length,this._cachedIndex=n,this.copySampleValue_(n-1)}if(n===o)break;if(s=a,a=e[++n],t<a)break t}r=e.length;break e}if(!(t>=s)){let o=e[1];t<o&&(n=2,s=o);for(let c=n-2;;){if(s===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(n===c)break;if(a=s,s=e[--n-1],t>=s)break t}r=n,n=0;break e}break n}for(;n<r;){let o=n+r>>>1;t<e[o]?r=o:n=o+1}if(a=e[n],s=e[n-1],s===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(a===void 0)return n=e.length,this._cachedIndex=n,this.copySampleValue_(n-1)}this._cachedIndex=n,this.intervalChanged_(n,s,a)}return this.interpolate_(n,s,t,a)}getSettings_(){return this.settings||this.DefaultSettings_}copySampleValue_(t){let e=this.resultBuffer,n=this.sampleValues,a=this.valueSize,s=t*a;for(let r=0;r!==a;++r)e[r]=n[s+r];return e}interpolate_(){throw new Error("THREE.Interpolant: Call to abstract method.")}intervalChanged_(){}},nc=class extends Gi{constructor(t,e,n,a){super(t,e,n,a),this._weightPrev=-0,this._offsetPrev=-0,this._weightNext=-0,this._offsetNext=-0,this.DefaultSettings_={endingStart:_h,endingEnd:_h}}intervalChanged_(t,e,n){let a=this.parameterPositions,s=t-2,r=t+1,o=a[s],c=a[r];if(o===void 0)switch(this.getSettings_().endingStart){case vh:s=t,o=2*e-n;break;case Mh:s=a.length-2,o=e+a[s]-a[s+1];break;default:s=t,o=n}if(c===void 0)switch(this.getSettings_().endingEnd){case vh:r=t,c=2*n-e;break;case Mh:r=1,c=n+a[1]-a[0];break;default:r=t-1,c=e}let l=(n-e)*.5,h=this.valueSize;this._weightPrev=l/(e-o),this._weightNext=l/(c-n),this._offsetPrev=s*h,this._offsetNext=r*h}interpolate_(t,e,n,a){let s=this.resultBuffer,r=this.sampleValues,o=this.valueSize,c=t*o,l=c-o,h=this._offsetPrev,u=this._offsetNext,d=this._weightPrev,f=this._weightNext,x=(n-e)/(a-e),v=x*x,m=v*x,g=-d*m+2*d*v-d*x,y=(1+d)*m+(-1.5-2*d)*v+(-.5+d)*x+1,w=(-1-f)*m+(1.5+f)*v+.5*x,p=f*m-f*v;for(let _=0;_!==o;++_)s[_]=g*r[h+_]+y*r[l+_]+w*r[c+_]+p*r[u+_];return s}},ic=class extends Gi{constructor(t,e,n,a){super(t,e,n,a)}interpolate_(t,e,n,a){let s=this.resultBuffer,r=this.sampleValues,o=this.valueSize,c=t*o,l=c-o,h=(n-e)/(a-e),u=1-h;for(let d=0;d!==o;++d)s[d]=r[l+d]*u+r[c+d]*h;return s}},ac=class extends Gi{constructor(t,e,n,a){super(t,e,n,a)}interpolate_(t){return this.copySampleValue_(t-1)}},sc=class extends Gi{interpolate_(t,e,n,a){let s=this.resultBuffer,r=this.sampleValues,o=this.valueSize,c=t*o,l=c-o,h=this.inTangents,u=this.outTangents;if(!h||!u){let x=(n-e)/(a-e),v=1-x;for(let m=0;m!==o;++m)s[m]=r[l+m]*v+r[c+m]*x;return s}let d=o*2,f=t-1;for(let x=0;x!==o;++x){let v=r[l+x],m=r[c+x],g=f*d+x*2,y=u[g],w=u[g+1],p=t*d+x*2,_=h[p],S=h[p+1],b=pb(n,e,y,_,a);s[x]=zf(b,v,w,S,m)}return s}};Pn=class{constructor(t,e,n,a){if(t===void 0)throw new Error("THREE.KeyframeTrack: track name is undefined");if(e===void 0||e.length===0)throw new Error("THREE.KeyframeTrack: no keyframes in track named "+t);this.name=t,this.times=Ga(e,this.TimeBufferType),this.values=Ga(n,this.ValueBufferType),this.setInterpolation(a||this.DefaultInterpolation)}static toJSON(t){let e=t.constructor,n;if(e.toJSON!==this.toJSON)n=e.toJSON(t);else{n={name:t.name,times:Ga(t.times,Array),values:Ga(t.values,Array)};let a=t.getInterpolation();a!==t.DefaultInterpolation&&(n.interpolation=a),Co(t.settings)&&(n.settings={inTangents:Ga(t.settings.inTangents,Array),outTangents:Ga(t.settings.outTangents,Array)})}return n.type=t.ValueTypeName,n}InterpolantFactoryMethodDiscrete(t){return new ac(this.times,this.values,this.getValueSize(),t)}InterpolantFactoryMethodLinear(t){return new ic(this.times,this.values,this.getValueSize(),t)}InterpolantFactoryMethodSmooth(t){return new nc(this.times,this.values,this.getValueSize(),t)}InterpolantFactoryMethodBezier(t){let e=new sc(this.times,this.values,this.getValueSize(),t);return this.settings&&(e.inTangents=this.settings.inTangents,e.outTangents=this.settings.outTangents),e}setInterpolation(t){let e;switch(t){case Js:e=this.InterpolantFactoryMethodDiscrete;break;case jo:e=this.InterpolantFactoryMethodLinear;break;case Do:e=this.InterpolantFactoryMethodSmooth;break;case yh:e=this.InterpolantFactoryMethodBezier;break}if(e===void 0){let n="unsupported interpolation for "+this.ValueTypeName+" keyframe track named "+this.name;if(this.createInterpolant===void 0)if(t!==this.DefaultInterpolation)this.setInterpolation(this.DefaultInterpolation);else throw new Error(n);return Ft("KeyframeTrack:",n),this}return this.createInterpolant=e,this}getInterpolation(){switch(this.createInterpolant){case this.InterpolantFactoryMethodDiscrete:return Js;case this.InterpolantFactoryMethodLinear:return jo;case this.InterpolantFactoryMethodSmooth:return Do;case this.InterpolantFactoryMethodBezier:return yh}}getValueSize(){return this.values.length/this.times.length}shift(t){if(t!==0){let e=this.times;for(let n=0,a=e.length;n!==a;++n)e[n]+=t;Co(this.settings)&&(qu(this.settings.inTangents,t),qu(this.settings.outTangents,t))}return this}scale(t){if(t!==1){let e=this.times;for(let n=0,a=e.length;n!==a;++n)e[n]*=t;Co(this.settings)&&(Yu(this.settings.inTangents,t),Yu(this.settings.outTangents,t))}return this}trim(t,e){let n=this.times,a=n.length,s=0,r=a-1;for(;s!==a&&n[s]<t;)++s;for(;r!==-1&&n[r]>e;)--r;if(++r,s!==0||r!==a){s>=r&&(r=Math.max(r,1),s=r-1);let o=this.getValueSize();this.times=n.slice(s,r),this.values=this.values.slice(s*o,r*o)}return this}validate(){let t=!0,e=this.getValueSize();e-Math.floor(e)!==0&&(zt("KeyframeTrack: Invalid value size in track.",this),t=!1);let n=this.times,a=this.values,s=n.length;s===0&&(zt("KeyframeTrack: Track is empty.",this),t=!1);let r=null;for(let o=0;o!==s;o++){let c=n[o];if(typeof c=="number"&&isNaN(c)){zt("KeyframeTrack: Time is not a valid number.",this,o,c),t=!1;break}if(r!==null&&r>c){zt("KeyframeTrack: Out of order keys.",this,o,c,r),t=!1;break}r=c}if(a!==void 0&&Sg(a))for(let o=0,c=a.length;o!==c;++o){let l=a[o];if(isNaN(l)){zt("KeyframeTrack: Value is not a valid number.",this,o,l),t=!1;break}}return t}optimize(){let t=this.times.slice(),e=this.values.slice(),n=this.getValueSize(),a=this.getInterpolation()===Do,s=t.length-1,r=1;for(let o=1;o<s;++o){let c=!1,l=t[o],h=t[o+1];if(l!==h&&(o!==1||l!==t[0]))if(a)c=!0;else{let u=o*n,d=u-n,f=u+n;for(let x=0;x!==n;++x){let v=e[u+x];if(v!==e[d+x]||v!==e[f+x]){c=!0;break}}}if(c){if(o!==r){t[r]=t[o];let u=o*n,d=r*n;for(let f=0;f!==n;++f)e[d+f]=e[u+f]}++r}}if(s>0){t[r]=t[s];for(let o=s*n,c=r*n,l=0;l!==n;++l)e[c+l]=e[o+l];++r}return r!==t.length?(this.times=t.slice(0,r),this.values=e.slice(0,r*n)):(this.times=t,this.values=e),this}clone(){let t=this.times.slice(),e=this.values.slice(),n=this.constructor,a=new n(this.name,t,e);return a.createInterpolant=this.createInterpolant,Co(this.settings)&&(a.settings={inTangents:this.settings.inTangents.slice(),outTangents:this.settings.outTangents.slice()}),a}};Pn.prototype.ValueTypeName="";Pn.prototype.TimeBufferType=Float32Array;Pn.prototype.ValueBufferType=Float32Array;Pn.prototype.DefaultInterpolation=jo;Wi=class extends Pn{constructor(t,e,n){super(t,e,n)}};Wi.prototype.ValueTypeName="bool";Wi.prototype.ValueBufferType=Array;Wi.prototype.DefaultInterpolation=Js;Wi.prototype.InterpolantFactoryMethodLinear=void 0;Wi.prototype.InterpolantFactoryMethodSmooth=void 0;rc=class extends Pn{constructor(t,e,n,a){super(t,e,n,a)}};rc.prototype.ValueTypeName="color";oc=class extends Pn{constructor(t,e,n,a){super(t,e,n,a)}};oc.prototype.ValueTypeName="number";cc=class extends Gi{constructor(t,e,n,a){super(t,e,n,a)}interpolate_(t,e,n,a){let s=this.resultBuffer,r=this.sampleValues,o=this.valueSize,c=(n-e)/(a-e),l=t*o;for(let h=l+o;l!==h;l+=4)Cn.slerpFlat(s,0,r,l-o,r,l,c);return s}},br=class extends Pn{constructor(t,e,n,a){super(t,e,n,a)}InterpolantFactoryMethodLinear(t){return new cc(this.times,this.values,this.getValueSize(),t)}};br.prototype.ValueTypeName="quaternion";br.prototype.InterpolantFactoryMethodSmooth=void 0;ji=class extends Pn{constructor(t,e,n){super(t,e,n)}};ji.prototype.ValueTypeName="string";ji.prototype.ValueBufferType=Array;ji.prototype.DefaultInterpolation=Js;ji.prototype.InterpolantFactoryMethodLinear=void 0;ji.prototype.InterpolantFactoryMethodSmooth=void 0;lc=class extends Pn{constructor(t,e,n,a){super(t,e,n,a)}};lc.prototype.ValueTypeName="vector";hc=class{constructor(t,e,n){let a=this,s=!1,r=0,o=0,c,l=[];this.onStart=void 0,this.onLoad=t,this.onProgress=e,this.onError=n,this._abortController=null,this.itemStart=function(h){o++,s===!1&&a.onStart!==void 0&&a.onStart(h,r,o),s=!0},this.itemEnd=function(h){r++,a.onProgress!==void 0&&a.onProgress(h,r,o),r===o&&(s=!1,a.onLoad!==void 0&&a.onLoad())},this.itemError=function(h){a.onError!==void 0&&a.onError(h)},this.resolveURL=function(h){return h=h.normalize("NFC"),c?c(h):h},this.setURLModifier=function(h){return c=h,this},this.addHandler=function(h,u){return l.push(h,u),this},this.removeHandler=function(h){let u=l.indexOf(h);return u!==-1&&l.splice(u,2),this},this.getHandler=function(h){for(let u=0,d=l.length;u<d;u+=2){let f=l[u],x=l[u+1];if(f.global&&(f.lastIndex=0),f.test(h))return x}return null},this.abort=function(){return this.abortController.abort(),this._abortController=null,this}}get abortController(){return this._abortController||(this._abortController=new AbortController),this._abortController}},Vf=new hc,dc=class{constructor(t){this.manager=t!==void 0?t:Vf,this.crossOrigin="anonymous",this.withCredentials=!1,this.path="",this.resourcePath="",this.requestHeader={},this.priority="auto",this.cache="default",typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}load(){}loadAsync(t,e){let n=this;return new Promise(function(a,s){n.load(t,a,e,s)})}parse(){}setCrossOrigin(t){return this.crossOrigin=t,this}setWithCredentials(t){return this.withCredentials=t,this}setPath(t){return this.path=t,this}setResourcePath(t){return this.resourcePath=t,this}setRequestHeader(t){return this.requestHeader=t,this}setPriority(t){return this.priority=t,this}setCache(t){return this.cache=t,this}abort(){return this}};dc.DEFAULT_MATERIAL_NAME="__DEFAULT";xr=class extends Fe{static registerNode(t){this.prototype._lightNode=t}constructor(t,e=1){super(),this.isLight=!0,this.type="Light",this.color=new jt(t),this.intensity=e}copy(t,e){return super.copy(t,e),this.color.copy(t.color),this.intensity=t.intensity,this}toJSON(t){let e=super.toJSON(t);return e.object.color=this.color.getHex(),e.object.intensity=this.intensity,e}},bh=new oe,Ju=new z,Ku=new z,uc=class{constructor(t){this.camera=t,this.intensity=1,this.bias=0,this.biasNode=null,this.normalBias=0,this.radius=1,this.blurSamples=8,this.mapSize=new Bt(512,512),this.mapType=an,this.map=null,this.mapPass=null,this.matrix=new oe,this.autoUpdate=!0,this.needsUpdate=!1,this._frustum=new Ri,this._frameExtents=new Bt(1,1),this._viewportCount=1,this._viewports=[new ce(0,0,1,1)]}getViewportCount(){return this._viewportCount}getCamera(){return this.camera}getFrustum(){return this._frustum}updateMatrices(t){let e=this.camera;Ju.setFromMatrixPosition(t.matrixWorld),e.position.copy(Ju),Ku.setFromMatrixPosition(t.target.matrixWorld),e.lookAt(Ku),e.updateMatrixWorld(),this._updateMatrix(e,this.matrix,this._frustum)}_updateMatrix(t,e,n,a){bh.multiplyMatrices(t.projectionMatrix,t.matrixWorldInverse),n.setFromProjectionMatrix(bh,t.coordinateSystem,t.reversedDepth);let s=this._frameExtents,r=a?a.z/s.x:1,o=a?a.w/s.y:1,c=a?a.x/s.x:0,l=a?a.y/s.y:0;t.coordinateSystem===Ka||t.reversedDepth?e.set(.5*r,0,0,.5*r+c,0,.5*o,0,.5*o+l,0,0,1,0,0,0,0,1):e.set(.5*r,0,0,.5*r+c,0,.5*o,0,.5*o+l,0,0,.5,.5,0,0,0,1),e.multiply(bh)}getViewport(t){return this._viewports[t]}getFrameExtents(){return this._frameExtents}dispose(){this.map&&this.map.dispose(),this.mapPass&&this.mapPass.dispose()}copy(t){return this.camera=t.camera.clone(),this.intensity=t.intensity,this.bias=t.bias,this.radius=t.radius,this.autoUpdate=t.autoUpdate,this.needsUpdate=t.needsUpdate,this.normalBias=t.normalBias,this.blurSamples=t.blurSamples,this.mapSize.copy(t.mapSize),this.mapType=t.mapType,this.biasNode=t.biasNode,this}clone(){return new this.constructor().copy(this)}toJSON(){let t={};return t.intensity=this.intensity,t.bias=this.bias,t.normalBias=this.normalBias,t.radius=this.radius,t.blurSamples=this.blurSamples,t.mapSize=this.mapSize.toArray(),t.mapType=this.mapType,t.camera=this.camera.toJSON(!1).object,delete t.camera.matrix,t}},No=new z,Po=new Cn,ii=new z,yr=class extends Fe{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new oe,this.projectionMatrix=new oe,this.projectionMatrixInverse=new oe,this.coordinateSystem=Fn,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(t,e){return super.copy(t,e),this.matrixWorldInverse.copy(t.matrixWorldInverse),this.projectionMatrix.copy(t.projectionMatrix),this.projectionMatrixInverse.copy(t.projectionMatrixInverse),this.coordinateSystem=t.coordinateSystem,this}getWorldDirection(t){return super.getWorldDirection(t).negate()}updateMatrixWorld(t){super.updateMatrixWorld(t),this.matrixWorld.decompose(No,Po,ii),ii.x===1&&ii.y===1&&ii.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(No,Po,ii.set(1,1,1)).invert()}updateWorldMatrix(t,e,n=!1){super.updateWorldMatrix(t,e,n),this.matrixWorld.decompose(No,Po,ii),ii.x===1&&ii.y===1&&ii.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(No,Po,ii.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}},Hi=new z,Zu=new Bt,Qu=new Bt,fn=class extends yr{constructor(t=50,e=1,n=.1,a=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=t,this.zoom=1,this.near=n,this.far=a,this.focus=10,this.aspect=e,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(t,e){return super.copy(t,e),this.fov=t.fov,this.zoom=t.zoom,this.near=t.near,this.far=t.far,this.focus=t.focus,this.aspect=t.aspect,this.view=t.view===null?null:Object.assign({},t.view),this.filmGauge=t.filmGauge,this.filmOffset=t.filmOffset,this}setFocalLength(t){let e=.5*this.getFilmHeight()/t;this.fov=Qa*2*Math.atan(e),this.updateProjectionMatrix()}getFocalLength(){let t=Math.tan(qs*.5*this.fov);return .5*this.getFilmHeight()/t}getEffectiveFOV(){return Qa*2*Math.atan(Math.tan(qs*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(t,e,n){Hi.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),e.set(Hi.x,Hi.y).multiplyScalar(-t/Hi.z),Hi.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),n.set(Hi.x,Hi.y).multiplyScalar(-t/Hi.z)}getViewSize(t,e){return this.getViewBounds(t,Zu,Qu),e.subVectors(Qu,Zu)}setViewOffset(t,e,n,a,s,r){this.aspect=t/e,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=t,this.view.fullHeight=e,this.view.offsetX=n,this.view.offsetY=a,this.view.width=s,this.view.height=r,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let t=this.near,e=t*Math.tan(qs*.5*this.fov)/this.zoom,n=2*e,a=this.aspect*n,s=-.5*a,r=this.view;if(this.view!==null&&this.view.enabled){let c=r.fullWidth,l=r.fullHeight;s+=r.offsetX*a/c,e-=r.offsetY*n/l,a*=r.width/c,n*=r.height/l}let o=this.filmOffset;o!==0&&(s+=t*o/this.getFilmWidth()),this.projectionMatrix.makePerspective(s,s+a,e,e-n,t,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(t){let e=super.toJSON(t);return e.object.fov=this.fov,e.object.zoom=this.zoom,e.object.near=this.near,e.object.far=this.far,e.object.focus=this.focus,e.object.aspect=this.aspect,this.view!==null&&(e.object.view=Object.assign({},this.view)),e.object.filmGauge=this.filmGauge,e.object.filmOffset=this.filmOffset,e}},_r=class extends yr{constructor(t=-1,e=1,n=1,a=-1,s=.1,r=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=t,this.right=e,this.top=n,this.bottom=a,this.near=s,this.far=r,this.updateProjectionMatrix()}copy(t,e){return super.copy(t,e),this.left=t.left,this.right=t.right,this.top=t.top,this.bottom=t.bottom,this.near=t.near,this.far=t.far,this.zoom=t.zoom,this.view=t.view===null?null:Object.assign({},t.view),this}setViewOffset(t,e,n,a,s,r){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=t,this.view.fullHeight=e,this.view.offsetX=n,this.view.offsetY=a,this.view.width=s,this.view.height=r,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let t=(this.right-this.left)/(2*this.zoom),e=(this.top-this.bottom)/(2*this.zoom),n=(this.right+this.left)/2,a=(this.top+this.bottom)/2,s=n-t,r=n+t,o=a+e,c=a-e;if(this.view!==null&&this.view.enabled){let l=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;s+=l*this.view.offsetX,r=s+l*this.view.width,o-=h*this.view.offsetY,c=o-h*this.view.height}this.projectionMatrix.makeOrthographic(s,r,o,c,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(t){let e=super.toJSON(t);return e.object.zoom=this.zoom,e.object.left=this.left,e.object.right=this.right,e.object.top=this.top,e.object.bottom=this.bottom,e.object.near=this.near,e.object.far=this.far,this.view!==null&&(e.object.view=Object.assign({},this.view)),e}},Ah=class extends uc{constructor(){super(new _r(-5,5,5,-5,.5,500)),this.isDirectionalLightShadow=!0}},vr=class extends xr{constructor(t,e){super(t,e),this.isDirectionalLight=!0,this.type="DirectionalLight",this.position.copy(Fe.DEFAULT_UP),this.updateMatrix(),this.target=new Fe,this.shadow=new Ah}dispose(){super.dispose(),this.shadow.dispose()}copy(t){return super.copy(t),this.target=t.target.clone(),this.shadow=t.shadow.clone(),this}toJSON(t){let e=super.toJSON(t);return e.object.shadow=this.shadow.toJSON(),e.object.target=this.target.uuid,e}},Mr=class extends xr{constructor(t,e){super(t,e),this.isAmbientLight=!0,this.type="AmbientLight"}},Sr=class extends Ue{constructor(){super(),this.isInstancedBufferGeometry=!0,this.type="InstancedBufferGeometry",this.instanceCount=1/0}copy(t){return super.copy(t),this.instanceCount=t.instanceCount,this}toJSON(){let t=super.toJSON();return t.instanceCount=this.instanceCount,t.isInstancedBufferGeometry=!0,t}},Wa=-90,ja=1,rs=class extends Fe{constructor(t,e,n){super(),this.type="CubeCamera",this.renderTarget=n,this.coordinateSystem=null,this.activeMipmapLevel=0;let a=new fn(Wa,ja,t,e);a.layers=this.layers,this.add(a);let s=new fn(Wa,ja,t,e);s.layers=this.layers,this.add(s);let r=new fn(Wa,ja,t,e);r.layers=this.layers,this.add(r);let o=new fn(Wa,ja,t,e);o.layers=this.layers,this.add(o);let c=new fn(Wa,ja,t,e);c.layers=this.layers,this.add(c);let l=new fn(Wa,ja,t,e);l.layers=this.layers,this.add(l)}updateCoordinateSystem(){let t=this.coordinateSystem,e=this.children.concat(),[n,a,s,r,o,c]=e;for(let l of e)this.remove(l);if(t===Fn)n.up.set(0,1,0),n.lookAt(1,0,0),a.up.set(0,1,0),a.lookAt(-1,0,0),s.up.set(0,0,-1),s.lookAt(0,1,0),r.up.set(0,0,1),r.lookAt(0,-1,0),o.up.set(0,1,0),o.lookAt(0,0,1),c.up.set(0,1,0),c.lookAt(0,0,-1);else if(t===Ka)n.up.set(0,-1,0),n.lookAt(-1,0,0),a.up.set(0,-1,0),a.lookAt(1,0,0),s.up.set(0,0,1),s.lookAt(0,1,0),r.up.set(0,0,-1),r.lookAt(0,-1,0),o.up.set(0,-1,0),o.lookAt(0,0,1),c.up.set(0,-1,0),c.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+t);for(let l of e)this.add(l),l.updateMatrixWorld()}update(t,e){this.parent===null&&this.updateMatrixWorld();let{renderTarget:n,activeMipmapLevel:a}=this;this.coordinateSystem!==t.coordinateSystem&&(this.coordinateSystem=t.coordinateSystem,this.updateCoordinateSystem());let[s,r,o,c,l,h]=this.children,u=t.getRenderTarget(),d=t.getActiveCubeFace(),f=t.getActiveMipmapLevel(),x=t.xr.enabled;t.xr.enabled=!1;let v=n.texture.mipmapsAutoUpdate;n.texture.mipmapsAutoUpdate=!1;let m=!1;t.isWebGLRenderer===!0?m=t.state.buffers.depth.getReversed():m=t.reversedDepthBuffer,t.setRenderTarget(n,0,a),m&&t.autoClear===!1&&t.clearDepth(),t.render(e,s),t.setRenderTarget(n,1,a),m&&t.autoClear===!1&&t.clearDepth(),t.render(e,r),t.setRenderTarget(n,2,a),m&&t.autoClear===!1&&t.clearDepth(),t.render(e,o),t.setRenderTarget(n,3,a),m&&t.autoClear===!1&&t.clearDepth(),t.render(e,c),t.setRenderTarget(n,4,a),m&&t.autoClear===!1&&t.clearDepth(),t.render(e,l),n.texture.mipmapsAutoUpdate=v,t.setRenderTarget(n,5,a),m&&t.autoClear===!1&&t.clearDepth(),t.render(e,h),t.setRenderTarget(u,d,f),t.xr.enabled=x,n.texture.needsPMREMUpdate=!0}},fc=class extends fn{constructor(t=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=t,this.perCameraFrustumCulled=!1}},id="\\[\\]\\.:\\/",mb=new RegExp("["+id+"]","g"),ad="[^"+id+"]",gb="[^"+id.replace("\\.","")+"]",bb=/((?:WC+[\/:])*)/.source.replace("WC",ad),xb=/(WCOD+)?/.source.replace("WCOD",gb),yb=/(?:\.(WC+)(?:\[(.+)\])?)?/.source.replace("WC",ad),_b=/\.(WC+)(?:\[(.+)\])?/.source.replace("WC",ad),vb=new RegExp("^"+bb+xb+yb+_b+"$"),Mb=["material","materials","bones","map"],Eh=class{constructor(t,e,n){let a=n||we.parseTrackName(e);this._targetGroup=t,this._bindings=t.subscribe_(e,a)}getValue(t,e){this.bind();let n=this._targetGroup.nCachedObjects_,a=this._bindings[n];a!==void 0&&a.getValue(t,e)}setValue(t,e){let n=this._bindings;for(let a=this._targetGroup.nCachedObjects_,s=n.length;a!==s;++a)n[a].setValue(t,e)}bind(){let t=this._bindings;for(let e=this._targetGroup.nCachedObjects_,n=t.length;e!==n;++e)t[e].bind()}unbind(){let t=this._bindings;for(let e=this._targetGroup.nCachedObjects_,n=t.length;e!==n;++e)t[e].unbind()}},we=class i{constructor(t,e,n){this.path=e,this.parsedPath=n||i.parseTrackName(e),this.node=i.findNode(t,this.parsedPath.nodeName),this.rootNode=t,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}static create(t,e,n){return t&&t.isAnimationObjectGroup?new i.Composite(t,e,n):new i(t,e,n)}static sanitizeNodeName(t){return t.replace(/\s/g,"_").replace(mb,"")}static parseTrackName(t){let e=vb.exec(t);if(e===null)throw new Error("THREE.PropertyBinding: Cannot parse trackName: "+t);let n={nodeName:e[2],objectName:e[3],objectIndex:e[4],propertyName:e[5],propertyIndex:e[6]},a=n.nodeName&&n.nodeName.lastIndexOf(".");if(a!==void 0&&a!==-1){let s=n.nodeName.substring(a+1);Mb.indexOf(s)!==-1&&(n.nodeName=n.nodeName.substring(0,a),n.objectName=s)}if(n.propertyName===null||n.propertyName.length===0)throw new Error("THREE.PropertyBinding: can not parse propertyName from trackName: "+t);return n}static findNode(t,e){if(e===void 0||e===""||e==="."||e===-1||e===t.name||e===t.uuid)return t;if(t.skeleton){let n=t.skeleton.getBoneByName(e);if(n!==void 0)return n}if(t.children){let n=function(s){for(let r=0;r<s.length;r++){let o=s[r];if(o.name===e||o.uuid===e)return o;let c=n(o.children);if(c)return c}return null},a=n(t.children);if(a)return a}return null}_getValue_unavailable(){}_setValue_unavailable(){}_getValue_direct(t,e){t[e]=this.targetObject[this.propertyName]}_getValue_array(t,e){let n=this.resolvedProperty;for(let a=0,s=n.length;a!==s;++a)t[e++]=n[a]}_getValue_arrayElement(t,e){t[e]=this.resolvedProperty[this.propertyIndex]}_getValue_toArray(t,e){this.resolvedProperty.toArray(t,e)}_setValue_direct(t,e){this.targetObject[this.propertyName]=t[e]}_setValue_direct_setNeedsUpdate(t,e){this.targetObject[this.propertyName]=t[e],this.targetObject.needsUpdate=!0}_setValue_direct_setMatrixWorldNeedsUpdate(t,e){this.targetObject[this.propertyName]=t[e],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_array(t,e){let n=this.resolvedProperty;for(let a=0,s=n.length;a!==s;++a)n[a]=t[e++]}_setValue_array_setNeedsUpdate(t,e){let n=this.resolvedProperty;for(let a=0,s=n.length;a!==s;++a)n[a]=t[e++];this.targetObject.needsUpdate=!0}_setValue_array_setMatrixWorldNeedsUpdate(t,e){let n=this.resolvedProperty;for(let a=0,s=n.length;a!==s;++a)n[a]=t[e++];this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_arrayElement(t,e){this.resolvedProperty[this.propertyIndex]=t[e]}_setValue_arrayElement_setNeedsUpdate(t,e){this.resolvedProperty[this.propertyIndex]=t[e],this.targetObject.needsUpdate=!0}_setValue_arrayElement_setMatrixWorldNeedsUpdate(t,e){this.resolvedProperty[this.propertyIndex]=t[e],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_fromArray(t,e){this.resolvedProperty.fromArray(t,e)}_setValue_fromArray_setNeedsUpdate(t,e){this.resolvedProperty.fromArray(t,e),this.targetObject.needsUpdate=!0}_setValue_fromArray_setMatrixWorldNeedsUpdate(t,e){this.resolvedProperty.fromArray(t,e),this.targetObject.matrixWorldNeedsUpdate=!0}_getValue_unbound(t,e){this.bind(),this.getValue(t,e)}_setValue_unbound(t,e){this.bind(),this.setValue(t,e)}bind(){let t=this.node,e=this.parsedPath,n=e.objectName,a=e.propertyName,s=e.propertyIndex;if(t||(t=i.findNode(this.rootNode,e.nodeName),this.node=t),this.getValue=this._getValue_unavailable,this.setValue=this._setValue_unavailable,!t){Ft("PropertyBinding: No target node found for track: "+this.path+".");return}if(n){let l=e.objectIndex;switch(n){case"materials":if(!t.material){zt("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!t.material.materials){zt("PropertyBinding: Can not bind to material.materials as node.material does not have a materials array.",this);return}t=t.material.materials;break;case"bones":if(!t.skeleton){zt("PropertyBinding: Can not bind to bones as node does not have a skeleton.",this);return}t=t.skeleton.bones;for(let h=0;h<t.length;h++)if(t[h].name===l){l=h;break}break;case"map":if("map"in t){t=t.map;break}if(!t.material){zt("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!t.material.map){zt("PropertyBinding: Can not bind to material.map as node.material does not have a map.",this);return}t=t.material.map;break;default:if(t[n]===void 0){zt("PropertyBinding: Can not bind to objectName of node undefined.",this);return}t=t[n]}if(l!==void 0){if(t[l]===void 0){zt("PropertyBinding: Trying to bind to objectIndex of objectName, but is undefined.",this,t);return}t=t[l]}}let r=t[a];if(r===void 0){let l=e.nodeName;zt("PropertyBinding: Trying to update property for track: "+l+"."+a+" but it wasn't found.",t);return}let o=this.Versioning.None;this.targetObject=t,t.isMaterial===!0?o=this.Versioning.NeedsUpdate:t.isObject3D===!0&&(o=this.Versioning.MatrixWorldNeedsUpdate);let c=this.BindingType.Direct;if(s!==void 0){if(a==="morphTargetInfluences"){if(!t.geometry){zt("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.",this);return}if(!t.geometry.morphAttributes){zt("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.morphAttributes.",this);return}t.morphTargetDictionary[s]!==void 0&&(s=t.morphTargetDictionary[s])}c=this.BindingType.ArrayElement,this.resolvedProperty=r,this.propertyIndex=s}else r.fromArray!==void 0&&r.toArray!==void 0?(c=this.BindingType.HasFromToArray,this.resolvedProperty=r):Array.isArray(r)?(c=this.BindingType.EntireArray,this.resolvedProperty=r):this.propertyName=a;this.getValue=this.GetterByBindingType[c],this.setValue=this.SetterByBindingTypeAndVersioning[c][o]}unbind(){this.node=null,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}};we.Composite=Eh;we.prototype.BindingType={Direct:0,EntireArray:1,ArrayElement:2,HasFromToArray:3};we.prototype.Versioning={None:0,NeedsUpdate:1,MatrixWorldNeedsUpdate:2};we.prototype.GetterByBindingType=[we.prototype._getValue_direct,we.prototype._getValue_array,we.prototype._getValue_arrayElement,we.prototype._getValue_toArray];we.prototype.SetterByBindingTypeAndVersioning=[[we.prototype._setValue_direct,we.prototype._setValue_direct_setNeedsUpdate,we.prototype._setValue_direct_setMatrixWorldNeedsUpdate],[we.prototype._setValue_array,we.prototype._setValue_array_setNeedsUpdate,we.prototype._setValue_array_setMatrixWorldNeedsUpdate],[we.prototype._setValue_arrayElement,we.prototype._setValue_arrayElement_setNeedsUpdate,we.prototype._setValue_arrayElement_setMatrixWorldNeedsUpdate],[we.prototype._setValue_fromArray,we.prototype._setValue_fromArray_setNeedsUpdate,we.prototype._setValue_fromArray_setMatrixWorldNeedsUpdate]];zM=new Float32Array(1),Xi=class extends Jo{constructor(t,e,n=1){super(t,e),this.isInstancedInterleavedBuffer=!0,this.meshPerAttribute=n}copy(t){return super.copy(t),this.meshPerAttribute=t.meshPerAttribute,this}clone(t){let e=super.clone(t);return e.meshPerAttribute=this.meshPerAttribute,e}toJSON(t){let e=super.toJSON(t);return e.isInstancedInterleavedBuffer=!0,e.meshPerAttribute=this.meshPerAttribute,e}},$u=new oe,wr=class{constructor(t,e,n=0,a=1/0){this.ray=new Kn(t,e),this.near=n,this.far=a,this.camera=null,this.layers=new ts,this.params={Mesh:{},Line:{threshold:1},LOD:{},Points:{threshold:1},Sprite:{}}}set(t,e){this.ray.set(t,e)}setFromCamera(t,e){e.isPerspectiveCamera?(this.ray.origin.setFromMatrixPosition(e.matrixWorld),this.ray.direction.set(t.x,t.y,.5).unproject(e).sub(this.ray.origin).normalize(),this.camera=e):e.isOrthographicCamera?(this.ray.origin.set(t.x,t.y,e.projectionMatrix.elements[14]).unproject(e),this.ray.direction.set(0,0,-1).transformDirection(e.matrixWorld),this.camera=e):zt("Raycaster: Unsupported camera type: "+e.type)}setFromXRController(t){return $u.identity().extractRotation(t.matrixWorld),this.ray.origin.setFromMatrixPosition(t.matrixWorld),this.ray.direction.set(0,0,-1).applyMatrix4($u),this}intersectObject(t,e=!0,n=[]){return Th(t,this,n,e),n.sort(tf),n}intersectObjects(t,e=!0,n=[]){for(let a=0,s=t.length;a<s;a++)Th(t[a],this,n,e);return n.sort(tf),n}};os=class{constructor(t=1,e=0,n=0){this.radius=t,this.phi=e,this.theta=n}set(t,e,n){return this.radius=t,this.phi=e,this.theta=n,this}copy(t){return this.radius=t.radius,this.phi=t.phi,this.theta=t.theta,this}makeSafe(){return this.phi=Wt(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(t){return this.setFromCartesianCoords(t.x,t.y,t.z)}setFromCartesianCoords(t,e,n){return this.radius=Math.sqrt(t*t+e*e+n*n),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(t,n),this.phi=Math.acos(Wt(e/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}},hd=class hd{constructor(t,e,n,a){this.elements=[1,0,0,1],t!==void 0&&this.set(t,e,n,a)}identity(){return this.set(1,0,0,1),this}fromArray(t,e=0){for(let n=0;n<4;n++)this.elements[n]=t[n+e];return this}set(t,e,n,a){let s=this.elements;return s[0]=t,s[2]=e,s[1]=n,s[3]=a,this}};hd.prototype.isMatrix2=!0;Ih=hd,ef=new z,Lo=new z,Xa=new z,qa=new z,xh=new z,Sb=new z,wb=new z,xa=class{constructor(t=new z,e=new z){this.start=t,this.end=e}set(t,e){return this.start.copy(t),this.end.copy(e),this}copy(t){return this.start.copy(t.start),this.end.copy(t.end),this}getCenter(t){return t.addVectors(this.start,this.end).multiplyScalar(.5)}delta(t){return t.subVectors(this.end,this.start)}distanceSq(){return this.start.distanceToSquared(this.end)}distance(){return this.start.distanceTo(this.end)}at(t,e){return this.delta(e).multiplyScalar(t).add(this.start)}closestPointToPointParameter(t,e){ef.subVectors(t,this.start),Lo.subVectors(this.end,this.start);let n=Lo.dot(Lo);if(n===0)return 0;let s=Lo.dot(ef)/n;return e&&(s=Wt(s,0,1)),s}closestPointToPoint(t,e,n){let a=this.closestPointToPointParameter(t,e);return this.delta(n).multiplyScalar(a).add(this.start)}distanceSqToLine3(t,e=Sb,n=wb){let a=10000000000000001e-32,s,r,o=this.start,c=t.start,l=this.end,h=t.end;Xa.subVectors(l,o),qa.subVectors(h,c),xh.subVectors(o,c);let u=Xa.dot(Xa),d=qa.dot(qa),f=qa.dot(xh);if(u<=a&&d<=a)return e.copy(o),n.copy(c),e.distanceToSquared(n);if(u<=a)s=0,r=f/d,r=Wt(r,0,1);else{let x=Xa.dot(xh);if(d<=a)r=0,s=Wt(-x/u,0,1);else{let v=Xa.dot(qa),m=u*d-v*v;m!==0?s=Wt((v*f-x*d)/m,0,1):s=0,r=(v*s+f)/d,r<0?(r=0,s=Wt(-x/u,0,1)):r>1&&(r=1,s=Wt((v-x)/u,0,1))}}return e.copy(o).addScaledVector(Xa,s),n.copy(c).addScaledVector(qa,r),e.distanceToSquared(n)}applyMatrix4(t){return this.start.applyMatrix4(t),this.end.applyMatrix4(t),this}equals(t){return t.start.equals(this.start)&&t.end.equals(this.end)}clone(){return new this.constructor().copy(this)}},Ar=class extends is{constructor(t=10,e=10,n=4473924,a=8947848){n=new jt(n),a=new jt(a);let s=e/2,r=t/e,o=t/2,c=[],l=[];for(let d=0,f=0,x=-o;d<=e;d++,x+=r){c.push(-o,0,x,o,0,x),c.push(x,0,-o,x,0,o);let v=d===s?n:a;v.toArray(l,f),f+=3,v.toArray(l,f),f+=3,v.toArray(l,f),f+=3,v.toArray(l,f),f+=3}let h=new Ue;h.setAttribute("position",new xe(c,3)),h.setAttribute("color",new xe(l,3));let u=new ga({vertexColors:!0,toneMapped:!1});super(h,u),this.type="GridHelper"}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}},Er=class extends Yn{constructor(t,e=null){super(),this.object=t,this.domElement=e,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(t){this.domElement!==null&&this.disconnect(),this.domElement=t}disconnect(){}dispose(){}update(){}};typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:"187"}}));typeof window<"u"&&(window.__THREE__?Ft("WARNING: Multiple instances of Three.js being imported."):window.__THREE__="187")});function lp(){let i=null,t=!1,e=null,n=null;function a(s,r){n=i.requestAnimationFrame(a),e(s,r)}return{start:function(){t!==!0&&e!==null&&i!==null&&(n=i.requestAnimationFrame(a),t=!0)},stop:function(){i!==null&&i.cancelAnimationFrame(n),t=!1},setAnimationLoop:function(s){e=s},setContext:function(s){i=s}}}function Eb(i){let t=new WeakMap;function e(o,c){let l=o.array,h=o.usage,u=l.byteLength,d=i.createBuffer();i.bindBuffer(c,d),i.bufferData(c,l,h),o.onUploadCallback();let f;if(l instanceof Float32Array)f=i.FLOAT;else if(typeof Float16Array<"u"&&l instanceof Float16Array)f=i.HALF_FLOAT;else if(l instanceof Uint16Array)o.isFloat16BufferAttribute?f=i.HALF_FLOAT:f=i.UNSIGNED_SHORT;else if(l instanceof Int16Array)f=i.SHORT;else if(l instanceof Uint32Array)f=i.UNSIGNED_INT;else if(l instanceof Int32Array)f=i.INT;else if(l instanceof Int8Array)f=i.BYTE;else if(l instanceof Uint8Array)f=i.UNSIGNED_BYTE;else if(l instanceof Uint8ClampedArray)f=i.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+l);return{buffer:d,type:f,bytesPerElement:l.BYTES_PER_ELEMENT,version:o.version,size:u}}function n(o,c,l){let h=c.array,u=c.updateRanges;if(i.bindBuffer(l,o),u.length===0)i.bufferSubData(l,0,h);else{u.sort((f,x)=>f.start-x.start);let d=0;for(let f=1;f<u.length;f++){let x=u[d],v=u[f];v.start<=x.start+x.count+1?x.count=Math.max(x.count,v.start+v.count-x.start):(++d,u[d]=v)}u.length=d+1;for(let f=0,x=u.length;f<x;f++){let v=u[f];i.bufferSubData(l,v.start*h.BYTES_PER_ELEMENT,h,v.start,v.count)}c.clearUpdateRanges()}c.onUploadCallback()}function a(o){return o.isInterleavedBufferAttribute&&(o=o.data),t.get(o)}function s(o){o.isInterleavedBufferAttribute&&(o=o.data);let c=t.get(o);c&&(i.deleteBuffer(c.buffer),t.delete(o))}function r(o,c){if(o.isInterleavedBufferAttribute&&(o=o.data),o.isGLBufferAttribute){let h=t.get(o);(!h||h.version<o.version)&&t.set(o,{buffer:o.buffer,type:o.type,bytesPerElement:o.elementSize,version:o.version});return}let l=t.get(o);if(l===void 0)t.set(o,e(o,c));else if(l.version<o.version){if(l.size!==o.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");n(l.buffer,o,c),l.version=o.version}}return{get:a,remove:s,update:r}}function oy(i,t,e,n,a,s){let r=new jt(0),o=a===!0?0:1,c,l,h=null,u=0,d=null;function f(y){let w=y.isScene===!0?y.background:null;if(w&&w.isTexture){let p=y.backgroundBlurriness>0;w=t.get(w,p)}return w}function x(y){let w=!1,p=f(y);p===null?m(r,o):p&&p.isColor&&(m(p,1),w=!0);let _=i.xr.getEnvironmentBlendMode();_==="additive"?e.buffers.color.setClear(0,0,0,1,s):_==="alpha-blend"&&e.buffers.color.setClear(0,0,0,0,s),(i.autoClear||w)&&(e.buffers.depth.setTest(!0),e.buffers.depth.setMask(!0),e.buffers.color.setMask(!0),i.clear(i.autoClearColor,i.autoClearDepth,i.autoClearStencil))}function v(y,w){let p=f(w);p&&p.isCubeTexture?(l===void 0&&(l=new nn(new as(1,1,1),new Bn({name:"BackgroundCubeMaterial",uniforms:Aa(xn.backgroundCube.uniforms),vertexShader:xn.backgroundCube.vertexShader,fragmentShader:xn.backgroundCube.fragmentShader,side:je,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),l.geometry.deleteAttribute("uv"),l.onBeforeRender=function(_,S,b){this.matrixWorld.copyPosition(b.matrixWorld)},Object.defineProperty(l.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),n.update(l)),l.material.uniforms.envMap.value=p,l.material.uniforms.backgroundBlurriness.value=w.backgroundBlurriness,l.material.uniforms.backgroundIntensity.value=w.backgroundIntensity,l.material.uniforms.backgroundRotation.value.setFromMatrix4(ry.makeRotationFromEuler(w.backgroundRotation)).transpose(),p.isRenderTargetTexture===!1&&l.material.uniforms.backgroundRotation.value.premultiply(hp),l.material.toneMapped=Kt.getTransfer(p.colorSpace)!==pe,(h!==p||u!==p.version||d!==i.toneMapping)&&(l.material.needsUpdate=!0,h=p,u=p.version,d=i.toneMapping),l.layers.enableAll(),y.unshift(l,l.geometry,l.material,0,0,null)):p&&p.isTexture&&(c===void 0&&(c=new nn(new ur(2,2),new Bn({name:"BackgroundMaterial",uniforms:Aa(xn.background.uniforms),vertexShader:xn.background.vertexShader,fragmentShader:xn.background.fragmentShader,side:ci,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),Object.defineProperty(c.material,"map",{get:function(){return this.uniforms.t2D.value}}),n.update(c)),c.material.uniforms.t2D.value=p,c.material.uniforms.backgroundIntensity.value=w.backgroundIntensity,c.material.toneMapped=Kt.getTransfer(p.colorSpace)!==pe,p.matrixAutoUpdate===!0&&p.updateMatrix(),c.material.uniforms.uvTransform.value.copy(p.matrix),(h!==p||u!==p.version||d!==i.toneMapping)&&(c.material.needsUpdate=!0,h=p,u=p.version,d=i.toneMapping),c.layers.enableAll(),y.unshift(c,c.geometry,c.material,0,0,null))}function m(y,w){y.getRGB(tl,nd(i)),e.buffers.color.setClear(tl.r,tl.g,tl.b,w,s)}function g(){l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0),c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0)}return{getClearColor:function(){return r},setClearColor:function(y,w=1){r.set(y),o=w,m(r,o)},getClearAlpha:function(){return o},setClearAlpha:function(y){o=y,m(r,o)},render:x,addToRenderList:v,dispose:g}}function cy(i,t){let e=i.getParameter(i.MAX_VERTEX_ATTRIBS),n={},a=d(null),s=a,r=!1;function o(I,N,L,P,U){let V=!1,O=u(I,P,L,N);s!==O&&(s=O,l(s.object)),V=f(I,P,L,U),V&&x(I,P,L,U),U!==null&&t.update(U,i.ELEMENT_ARRAY_BUFFER),(V||r)&&(r=!1,p(I,N,L,P),U!==null&&i.bindBuffer(i.ELEMENT_ARRAY_BUFFER,t.get(U).buffer))}function c(){return i.createVertexArray()}function l(I){return i.bindVertexArray(I)}function h(I){return i.deleteVertexArray(I)}function u(I,N,L,P){let U=P.wireframe===!0,V=n[N.id];V===void 0&&(V={},n[N.id]=V);let O=I.isInstancedMesh===!0?I.id:0,Q=V[O];Q===void 0&&(Q={},V[O]=Q);let G=Q[L.id];G===void 0&&(G={},Q[L.id]=G);let Z=G[U];return Z===void 0&&(Z=d(c()),G[U]=Z),Z}function d(I){let N=[],L=[],P=[];for(let U=0;U<e;U++)N[U]=0,L[U]=0,P[U]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:N,enabledAttributes:L,attributeDivisors:P,object:I,attributes:{},index:null}}function f(I,N,L,P){let U=s.attributes,V=N.attributes,O=0,Q=L.getAttributes();for(let G in Q)if(Q[G].location>=0){let et=U[G],ht=V[G];if(ht===void 0&&(G==="instanceMatrix"&&I.instanceMatrix&&(ht=I.instanceMatrix),G==="instanceColor"&&I.instanceColor&&(ht=I.instanceColor)),et===void 0||et.attribute!==ht||ht&&et.data!==ht.data)return!0;O++}return s.attributesNum!==O||s.index!==P}function x(I,N,L,P){let U={},V=N.attributes,O=0,Q=L.getAttributes();for(let G in Q)if(Q[G].location>=0){let et=V[G];et===void 0&&(G==="instanceMatrix"&&I.instanceMatrix&&(et=I.instanceMatrix),G==="instanceColor"&&I.instanceColor&&(et=I.instanceColor));let ht={};ht.attribute=et,et&&et.data&&(ht.data=et.data),U[G]=ht,O++}s.attributes=U,s.attributesNum=O,s.index=P}function v(){let I=s.newAttributes;for(let N=0,L=I.length;N<L;N++)I[N]=0}function m(I){g(I,0)}function g(I,N){let L=s.newAttributes,P=s.enabledAttributes,U=s.attributeDivisors;L[I]=1,P[I]===0&&(i.enableVertexAttribArray(I),P[I]=1),U[I]!==N&&(i.vertexAttribDivisor(I,N),U[I]=N)}function y(){let I=s.newAttributes,N=s.enabledAttributes;for(let L=0,P=N.length;L<P;L++)N[L]!==I[L]&&(i.disableVertexAttribArray(L),N[L]=0)}function w(I,N,L,P,U,V,O){O===!0?i.vertexAttribIPointer(I,N,L,U,V):i.vertexAttribPointer(I,N,L,P,U,V)}function p(I,N,L,P){v();let U=P.attributes,V=L.getAttributes(),O=N.defaultAttributeValues;for(let Q in V){let G=V[Q];if(G.location>=0){let Z=U[Q];if(Z===void 0&&(Q==="instanceMatrix"&&I.instanceMatrix&&(Z=I.instanceMatrix),Q==="instanceColor"&&I.instanceColor&&(Z=I.instanceColor)),Z!==void 0){let et=Z.normalized,ht=Z.itemSize,Pt=t.get(Z);if(Pt===void 0)continue;let Y=Pt.buffer,ct=Pt.type,mt=Pt.bytesPerElement,Tt=ct===i.INT||ct===i.UNSIGNED_INT||Z.gpuType===ds;if(Z.isInterleavedBufferAttribute){let gt=Z.data,Ot=gt.isInterleavedBuffer===!0?gt.stride:gt.itemSize,ge=Z.offset;if(gt.isInstancedInterleavedBuffer||gt.isInstancedBufferAttribute){for(let Dt=0;Dt<G.locationSize;Dt++)g(G.location+Dt,gt.meshPerAttribute);I.isInstancedMesh!==!0&&P._maxInstanceCount===void 0&&(P._maxInstanceCount=gt.meshPerAttribute*gt.count)}else for(let Dt=0;Dt<G.locationSize;Dt++)m(G.location+Dt);i.bindBuffer(i.ARRAY_BUFFER,Y);for(let Dt=0;Dt<G.locationSize;Dt++)w(G.location+Dt,ht/G.locationSize,ct,et,Ot*mt,(ge+ht/G.locationSize*Dt)*mt,Tt)}else{if(Z.isInstancedBufferAttribute){for(let gt=0;gt<G.locationSize;gt++)g(G.location+gt,Z.meshPerAttribute);I.isInstancedMesh!==!0&&P._maxInstanceCount===void 0&&(P._maxInstanceCount=Z.meshPerAttribute*Z.count)}else for(let gt=0;gt<G.locationSize;gt++)m(G.location+gt);i.bindBuffer(i.ARRAY_BUFFER,Y);for(let gt=0;gt<G.locationSize;gt++)w(G.location+gt,ht/G.locationSize,ct,et,ht*mt,ht/G.locationSize*gt*mt,Tt)}}else if(O!==void 0){let et=O[Q];if(et!==void 0)switch(et.length){case 2:i.vertexAttrib2fv(G.location,et);break;case 3:i.vertexAttrib3fv(G.location,et);break;case 4:i.vertexAttrib4fv(G.location,et);break;default:i.vertexAttrib1fv(G.location,et)}}}}y()}function _(){E();for(let I in n){let N=n[I];for(let L in N){let P=N[L];for(let U in P){let V=P[U];for(let O in V)h(V[O].object),delete V[O];delete P[U]}}delete n[I]}}function S(I){if(n[I.id]===void 0)return;let N=n[I.id];for(let L in N){let P=N[L];for(let U in P){let V=P[U];for(let O in V)h(V[O].object),delete V[O];delete P[U]}}delete n[I.id]}function b(I){for(let N in n){let L=n[N];for(let P in L){let U=L[P];if(U[I.id]===void 0)continue;let V=U[I.id];for(let O in V)h(V[O].object),delete V[O];delete U[I.id]}}}function M(I){for(let N in n){let L=n[N],P=I.isInstancedMesh===!0?I.id:0,U=L[P];if(U!==void 0){for(let V in U){let O=U[V];for(let Q in O)h(O[Q].object),delete O[Q];delete U[V]}delete L[P],Object.keys(L).length===0&&delete n[N]}}}function E(){A(),r=!0,s!==a&&(s=a,l(s.object))}function A(){a.geometry=null,a.program=null,a.wireframe=!1}return{setup:o,reset:E,resetDefaultState:A,dispose:_,releaseStatesOfGeometry:S,releaseStatesOfObject:M,releaseStatesOfProgram:b,initAttributes:v,enableAttribute:m,disableUnusedAttributes:y}}function ly(i,t,e){let n;function a(c){n=c}function s(c,l){i.drawArrays(n,c,l),e.update(l,n,1)}function r(c,l,h){h!==0&&(i.drawArraysInstanced(n,c,l,h),e.update(l,n,h))}function o(c,l,h){if(h===0)return;t.get("WEBGL_multi_draw").multiDrawArraysWEBGL(n,c,0,l,0,h);let d=0;for(let f=0;f<h;f++)d+=l[f];e.update(d,n,1)}this.setMode=a,this.render=s,this.renderInstances=r,this.renderMultiDraw=o}function hy(i,t,e,n){let a;function s(){if(a!==void 0)return a;if(t.has("EXT_texture_filter_anisotropic")===!0){let b=t.get("EXT_texture_filter_anisotropic");a=i.getParameter(b.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else a=0;return a}function r(b){return!(b!==bn&&n.convert(b)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_FORMAT))}function o(b){let M=b===Zn&&(t.has("EXT_color_buffer_half_float")||t.has("EXT_color_buffer_float"));return!(b!==an&&b!==gn&&!M&&n.convert(b)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_TYPE))}function c(b){if(b==="highp"){if(i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.HIGH_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.HIGH_FLOAT).precision>0)return"highp";b="mediump"}return b==="mediump"&&i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.MEDIUM_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let l=e.precision!==void 0?e.precision:"highp",h=c(l);h!==l&&(Ft("WebGLRenderer:",l,"not supported, using",h,"instead."),l=h);let u=e.reversedDepthBuffer===!0&&t.has("EXT_clip_control"),d=e.logarithmicDepthBuffer===!0&&u===!1;e.reversedDepthBuffer===!0&&u===!1&&Ft("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),e.logarithmicDepthBuffer===!0&&u===!0&&Ft("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");let f=i.getParameter(i.MAX_TEXTURE_IMAGE_UNITS),x=i.getParameter(i.MAX_VERTEX_TEXTURE_IMAGE_UNITS),v=i.getParameter(i.MAX_TEXTURE_SIZE),m=i.getParameter(i.MAX_CUBE_MAP_TEXTURE_SIZE),g=i.getParameter(i.MAX_VERTEX_ATTRIBS),y=i.getParameter(i.MAX_VERTEX_UNIFORM_VECTORS),w=i.getParameter(i.MAX_VARYING_VECTORS),p=i.getParameter(i.MAX_FRAGMENT_UNIFORM_VECTORS),_=i.getParameter(i.MAX_SAMPLES),S=i.getParameter(i.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:s,getMaxPrecision:c,textureFormatReadable:r,textureTypeReadable:o,precision:l,logarithmicDepthBuffer:d,reversedDepthBuffer:u,maxTextures:f,maxVertexTextures:x,maxTextureSize:v,maxCubemapSize:m,maxAttributes:g,maxVertexUniforms:y,maxVaryings:w,maxFragmentUniforms:p,maxSamples:_,samples:S}}function dy(i){let t=this,e=null,n=0,a=!1,s=!1,r=new un,o=new Vt,c={value:null,needsUpdate:!1};this.uniform=c,this.numPlanes=0,this.numIntersection=0,this.init=function(u,d){let f=u.length!==0||d||n!==0||a;return a=d,n=u.length,f},this.beginShadows=function(){s=!0,h(null)},this.endShadows=function(){s=!1},this.setGlobalState=function(u,d){e=h(u,d,0)},this.setState=function(u,d,f){let x=u.clippingPlanes,v=u.clipIntersection,m=u.clipShadows,g=i.get(u);if(!a||x===null||x.length===0||s&&!m)s?h(null):l();else{let y=s?0:n,w=y*4,p=g.clippingState||null;c.value=p,p=h(x,d,w,f);for(let _=0;_!==w;++_)p[_]=e[_];g.clippingState=p,this.numIntersection=v?this.numPlanes:0,this.numPlanes+=y}};function l(){c.value!==e&&(c.value=e,c.needsUpdate=n>0),t.numPlanes=n,t.numIntersection=0}function h(u,d,f,x){let v=u!==null?u.length:0,m=null;if(v!==0){if(m=c.value,x!==!0||m===null){let g=f+v*4,y=d.matrixWorldInverse;o.getNormalMatrix(y),(m===null||m.length<g)&&(m=new Float32Array(g));for(let w=0,p=f;w!==v;++w,p+=4)r.copy(u[w]).applyMatrix4(y,o),r.normal.toArray(m,p),m[p+3]=r.constant}c.value=m,c.needsUpdate=!0}return t.numPlanes=v,t.numIntersection=0,m}}function Gf(i,t,e){return new Vr(i,{minFilter:Ni,generateMipmaps:t,type:Zn,colorSpace:Ks,depthBuffer:e})}function Hr(i,t,e){return new Bn({name:i,uniforms:t,vertexShader:qt.cube_vert,fragmentShader:e,side:je,blending:ya,depthTest:!1,depthWrite:!1})}function by(){return Hr("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${dp}u

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float lodBias;

		#include <common>

		// Van der Corput radical inverse
		float radicalInverse_VdC( uint bits ) {

			bits = ( bits << 16u ) | ( bits >> 16u );
			bits = ( ( bits & 0x55555555u ) << 1u ) | ( ( bits & 0xAAAAAAAAu ) >> 1u );
			bits = ( ( bits & 0x33333333u ) << 2u ) | ( ( bits & 0xCCCCCCCCu ) >> 2u );
			bits = ( ( bits & 0x0F0F0F0Fu ) << 4u ) | ( ( bits & 0xF0F0F0F0u ) >> 4u );
			bits = ( ( bits & 0x00FF00FFu ) << 8u ) | ( ( bits & 0xFF00FF00u ) >> 8u );
			return float( bits ) * 2.3283064365386963e-10; // / 0x100000000

		}

		// Hammersley sequence
		vec2 hammersley( uint i, uint N ) {

			return vec2( float( i ) / float( N ), radicalInverse_VdC( i ) );

		}

		void main() {

			vec3 N = normalize( vWorldDirection );

			// For very low roughness, just sample the environment directly
			if ( roughness < 0.001 ) {

				gl_FragColor = vec4( textureLod( envMap, N, 0.0 ).rgb, 1.0 );
				return;

			}

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			// Tangent space basis for VNDF sampling
			vec3 up = abs( N.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, N ) );
			vec3 bitangent = cross( N, tangent );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			for ( uint i = 0u; i < GGX_SAMPLES; i ++ ) {

				vec2 Xi = hammersley( i, GGX_SAMPLES );

				// With V = N, sample the reflected direction directly.
				float invQ = 1.0 / ( 1.0 - Xi.x + alpha2 * Xi.x );
				float NdotL = ( 1.0 - Xi.x - alpha2 * Xi.x ) * invQ;

				if ( NdotL > 0.0 ) {

					float phi = 2.0 * PI * Xi.y;
					float sinTheta = 2.0 * alpha * sqrt( Xi.x * ( 1.0 - Xi.x ) ) * invQ;
					vec3 L = N * NdotL + ( tangent * cos( phi ) + bitangent * sin( phi ) ) * sinTheta;

					// Match the source mip to the sample's solid angle. The terms
					// independent of the sample are precomputed in lodBias.
					float d = alpha2 * invQ;
					float lod = max( log2( d ) + lodBias, 0.0 );

					// Weight by NdotL for the split-sum approximation
					prefilteredColor += textureLod( envMap, L, lod ).rgb * NdotL;
					totalWeight += NdotL;

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function xy(){return Hr("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:up}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float sourceLod;
		uniform int sourceSize;

		void main() {

			vec3 N = normalize( vWorldDirection );

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			float texelSize = 2.0 / float( sourceSize );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			// Pair opposite texels: only the one in N's hemisphere contributes.
			for ( int face = 0; face < 3; face ++ ) {

				for ( int y = 0; y < sourceSize; y ++ ) {

					for ( int x = 0; x < sourceSize; x ++ ) {

						vec2 uv = ( vec2( x, y ) + 0.5 ) * texelSize - 1.0;
						vec3 texelDirection = face == 0 ? vec3( 1.0, uv ) : ( face == 1 ? vec3( uv.x, 1.0, uv.y ) : vec3( uv, 1.0 ) );

						float invDistance = inversesqrt( 1.0 + dot( uv, uv ) );
						float NdotL = dot( N, texelDirection );
						texelDirection *= NdotL < 0.0 ? - 1.0 : 1.0;
						NdotL = abs( NdotL ) * invDistance;

						// With V = N, NdotH squared is ( 1 + NdotL ) / 2. Common factors
						// in the GGX distribution and texel solid angle cancel when normalized.
						float d = 1.0 + alpha2 + ( alpha2 - 1.0 ) * NdotL;
						float weight = NdotL * invDistance * invDistance * invDistance / ( d * d );

						prefilteredColor += textureLod( envMap, texelDirection, sourceLod ).rgb * weight;
						totalWeight += weight;

					}

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function yy(){return Hr("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${fy}
		#define GOLDEN_ANGLE 2.39996322973

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float sigma;

		#include <common>

		void main() {

			vec3 outputDirection = normalize( vWorldDirection );

			vec3 up = abs( outputDirection.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, outputDirection ) );
			vec3 bitangent = cross( outputDirection, tangent );

			// Truncate the kernel at three standard deviations or at the antipode.
			float thetaMax = min( 3.0 * sigma, PI );
			float truncation = 1.0 - exp( - 0.5 * thetaMax * thetaMax / ( sigma * sigma ) );

			vec3 accumColor = vec3( 0.0 );
			float accumWeight = 0.0;

			for ( int i = 0; i < SAMPLES; i ++ ) {

				// Stratified inverse-CDF sampling of the Gaussian, placed on a golden-angle spiral.
				float stratum = ( float( i ) + 0.5 ) / float( SAMPLES );
				float theta = sigma * sqrt( - 2.0 * log( 1.0 - stratum * truncation ) );
				float phi = float( i ) * GOLDEN_ANGLE;

				vec3 offset = cos( phi ) * tangent + sin( phi ) * bitangent;
				vec3 sampleDirection = cos( theta ) * outputDirection + sin( theta ) * offset;

				// Correct the planar sample density to solid angle.
				float weight = sin( theta ) / theta;

				accumColor += weight * textureLod( envMap, sampleDirection, 0.0 ).rgb;
				accumWeight += weight;

			}

			gl_FragColor = vec4( accumColor / accumWeight, 1.0 );

		}
	`)}function Wf(){return Hr("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

		varying vec3 vWorldDirection;

		uniform sampler2D envMap;

		#include <common>

		void main() {

			// Average four subpixel samples to preserve small, bright features.
			vec3 direction = normalize( vWorldDirection );
			vec3 dx = dFdx( direction ) * 0.25;
			vec3 dy = dFdy( direction ) * 0.25;

			vec3 color = textureLod( envMap, equirectUv( normalize( direction - dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction - dx + dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx + dy ) ), 0.0 ).rgb;
			gl_FragColor = vec4( color * 0.25, 1.0 );

		}
	`)}function jf(){return Hr("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function _y(i){let t=new WeakMap,e=new WeakMap,n=null;function a(d,f=!1){return d==null?null:f?r(d):s(d)}function s(d){if(d&&d.isTexture){let f=d.mapping;if(f===bc||f===xc)if(t.has(d)){let x=t.get(d).texture;return o(x,d.mapping)}else{let x=d.image;if(x&&x.height>0){let v=new Vr(x.height);return v.fromEquirectangularTexture(i,d),t.set(d,v),d.addEventListener("dispose",l),o(v.texture,d.mapping)}else return null}}return d}function r(d){if(d&&d.isTexture&&d.isPMREMTexture!==!0){let f=d.mapping,x=f===bc||f===xc,v=f===va||f===hs;if(x||v){let m=e.get(d),g=m!==void 0?m.texture.pmremVersion:0;if(d.isRenderTargetTexture&&d.pmremVersion!==g)return n===null&&(n=new nl(i)),m=x?n.fromEquirectangular(d,m):n.fromCubemap(d,m),m.texture.pmremVersion=d.pmremVersion,e.set(d,m),m.texture;if(m!==void 0)return m.texture;{let y=d.image;return x&&y&&y.height>0||v&&y&&c(y)?(n===null&&(n=new nl(i)),m=x?n.fromEquirectangular(d):n.fromCubemap(d),m.texture.pmremVersion=d.pmremVersion,e.set(d,m),d.addEventListener("dispose",h),m.texture):null}}}return d}function o(d,f){return f===bc?d.mapping=va:f===xc&&(d.mapping=hs),d}function c(d){let f=0,x=6;for(let v=0;v<x;v++)d[v]!==void 0&&f++;return f===x}function l(d){let f=d.target;f.removeEventListener("dispose",l);let x=t.get(f);x!==void 0&&(t.delete(f),x.dispose())}function h(d){let f=d.target;f.removeEventListener("dispose",h);let x=e.get(f);x!==void 0&&(e.delete(f),x.dispose())}function u(){t=new WeakMap,e=new WeakMap,n!==null&&(n.dispose(),n=null)}return{get:a,dispose:u}}function vy(i){let t={};function e(n){if(t[n]!==void 0)return t[n];let a=i.getExtension(n);return t[n]=a,a}return{has:function(n){return e(n)!==null},init:function(){e("EXT_color_buffer_float"),e("WEBGL_clip_cull_distance"),e("OES_texture_float_linear"),e("EXT_color_buffer_half_float"),e("WEBGL_multisampled_render_to_texture"),e("WEBGL_render_shared_exponent")},get:function(n){let a=e(n);return a===null&&Xs("WebGLRenderer: "+n+" extension not supported."),a}}}function My(i,t,e,n){let a={},s=new WeakMap,r=new FinalizationRegistry(x=>delete a[x]);function o(x){c(x.target)}function c(x){x.index!==null&&t.remove(x.index);for(let m in x.attributes)t.remove(x.attributes[m]);x.removeEventListener("dispose",o),delete a[x.id],r.unregister(x);let v=s.get(x);v&&(t.remove(v),s.delete(x)),n.releaseStatesOfGeometry(x),x.isInstancedBufferGeometry===!0&&delete x._maxInstanceCount,e.memory.geometries--}function l(x,v){return a[v.id]!==void 0||(v.addEventListener("dispose",o),a[v.id]=new WeakRef(v),r.register(v,v.id,v),e.memory.geometries++),v}function h(x){let v=x.attributes;for(let m in v)t.update(v[m],i.ARRAY_BUFFER)}function u(x){let v=x.index,m=x.attributes.position,g=0;if(m===void 0)return;let y=v!==null?v.array.length:m.array.length/3-1,w=m.count>=65535?ir:nr,p=new w(Math.ceil(y/3)*6,1),_=p.array;if(v!==null){let b=v.array;g=v.version;for(let M=0,E=0;M<y;M+=3){let A=b[M+0],I=b[M+1],N=b[M+2];_[E++]=A,_[E++]=I,_[E++]=I,_[E++]=N,_[E++]=N,_[E++]=A}}else{g=m.version;for(let b=0,M=0;b<y;b+=3){let E=b+0,A=b+1,I=b+2;_[M++]=E,_[M++]=A,_[M++]=A,_[M++]=I,_[M++]=I,_[M++]=E}}p.version=g;let S=s.get(x);S&&t.remove(S),s.set(x,p)}function d(x){let v=s.get(x);if(v){let m=x.index;m!==null&&v.version<m.version&&u(x)}else u(x);return s.get(x)}function f(){for(let x in a){let v=a[x].deref();v!==void 0&&c(v)}}return{get:l,update:h,getWireframeAttribute:d,dispose:f}}function Sy(i,t,e){let n;function a(u){n=u}let s,r;function o(u){s=u.type,r=u.bytesPerElement}function c(u,d){i.drawElements(n,d,s,u*r),e.update(d,n,1)}function l(u,d,f){f!==0&&(i.drawElementsInstanced(n,d,s,u*r,f),e.update(d,n,f))}function h(u,d,f){if(f===0)return;t.get("WEBGL_multi_draw").multiDrawElementsWEBGL(n,d,0,s,u,0,f);let v=0;for(let m=0;m<f;m++)v+=d[m];e.update(v,n,1)}this.setMode=a,this.setIndex=o,this.render=c,this.renderInstances=l,this.renderMultiDraw=h}function wy(i){let t={geometries:0,textures:0},e={frame:0,calls:0,triangles:0,points:0,lines:0};function n(s,r,o){switch(e.calls++,r){case i.TRIANGLES:e.triangles+=o*(s/3);break;case i.LINES:e.lines+=o*(s/2);break;case i.LINE_STRIP:e.lines+=o*(s-1);break;case i.LINE_LOOP:e.lines+=o*s;break;case i.POINTS:e.points+=o*s;break;default:zt("WebGLInfo: Unknown draw mode:",r);break}}function a(){e.calls=0,e.triangles=0,e.points=0,e.lines=0}return{memory:t,render:e,programs:null,autoReset:!0,reset:a,update:n}}function Ay(i,t,e){let n=new WeakMap,a=new ce;function s(r,o,c){let l=r.morphTargetInfluences,h=o.morphAttributes.position||o.morphAttributes.normal||o.morphAttributes.color,u=h!==void 0?h.length:0,d=n.get(o);if(d===void 0||d.count!==u){let E=function(){b.dispose(),n.delete(o),o.removeEventListener("dispose",E)};d!==void 0&&d.texture.dispose();let f=o.morphAttributes.position!==void 0,x=o.morphAttributes.normal!==void 0,v=o.morphAttributes.color!==void 0,m=o.morphAttributes.position||[],g=o.morphAttributes.normal||[],y=o.morphAttributes.color||[],w=0;f===!0&&(w=1),x===!0&&(w=2),v===!0&&(w=3);let p=o.attributes.position.count*w,_=1;p>t.maxTextureSize&&(_=Math.ceil(p/t.maxTextureSize),p=t.maxTextureSize);let S=new Float32Array(p*_*4*u),b=new tr(S,p,_,u);b.type=gn,b.needsUpdate=!0;let M=w*4;for(let A=0;A<u;A++){let I=m[A],N=g[A],L=y[A],P=p*_*4*A;for(let U=0;U<I.count;U++){let V=U*M;f===!0&&(a.fromBufferAttribute(I,U),S[P+V+0]=a.x,S[P+V+1]=a.y,S[P+V+2]=a.z,S[P+V+3]=0),x===!0&&(a.fromBufferAttribute(N,U),S[P+V+4]=a.x,S[P+V+5]=a.y,S[P+V+6]=a.z,S[P+V+7]=0),v===!0&&(a.fromBufferAttribute(L,U),S[P+V+8]=a.x,S[P+V+9]=a.y,S[P+V+10]=a.z,S[P+V+11]=L.itemSize===4?a.w:1)}}d={count:u,texture:b,size:new Bt(p,_)},n.set(o,d),o.addEventListener("dispose",E)}if(r.isInstancedMesh===!0&&r.morphTexture!==null)c.getUniforms().setValue(i,"morphTexture",r.morphTexture,e);else{let f=0;for(let v=0;v<l.length;v++)f+=l[v];let x=o.morphTargetsRelative?1:1-f;c.getUniforms().setValue(i,"morphTargetBaseInfluence",x),c.getUniforms().setValue(i,"morphTargetInfluences",l)}c.getUniforms().setValue(i,"morphTargetsTexture",d.texture,e),c.getUniforms().setValue(i,"morphTargetsTextureSize",d.size)}return{update:s}}function Ey(i,t,e,n,a){let s=new WeakMap;function r(l){let h=a.render.frame,u=l.geometry,d=t.get(l,u);if(s.get(d)!==h&&(t.update(d),s.set(d,h)),l.isInstancedMesh&&(l.hasEventListener("dispose",c)===!1&&l.addEventListener("dispose",c),s.get(l)!==h&&(e.update(l.instanceMatrix,i.ARRAY_BUFFER),l.instanceColor!==null&&e.update(l.instanceColor,i.ARRAY_BUFFER),s.set(l,h))),l.isSkinnedMesh){let f=l.skeleton;s.get(f)!==h&&(f.update(),s.set(f,h))}return d}function o(){s=new WeakMap}function c(l){let h=l.target;h.removeEventListener("dispose",c),n.releaseStatesOfObject(h),e.remove(h.instanceMatrix),h.instanceColor!==null&&e.remove(h.instanceColor)}return{update:r,dispose:o}}function Iy(i,t,e,n,a,s){let r=new Nn(t,e,{type:i,depthBuffer:a,stencilBuffer:s,samples:n?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1}),o=null,c=null,l=null,h=new Ue;h.setAttribute("position",new xe([-1,3,0,-1,-1,0,3,-1,0],3)),h.setAttribute("uv",new xe([0,2,0,0,2,0],2));let u=new $o({uniforms:{tDiffuse:{value:null}},vertexShader:`
			precision highp float;

			uniform mat4 modelViewMatrix;
			uniform mat4 projectionMatrix;

			attribute vec3 position;
			attribute vec2 uv;

			varying vec2 vUv;

			void main() {
				vUv = uv;
				gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
			}`,fragmentShader:`
			precision highp float;

			uniform sampler2D tDiffuse;

			varying vec2 vUv;

			#include <tonemapping_pars_fragment>
			#include <colorspace_pars_fragment>

			void main() {
				gl_FragColor = texture2D( tDiffuse, vUv );

				#ifdef LINEAR_TONE_MAPPING
					gl_FragColor.rgb = LinearToneMapping( gl_FragColor.rgb );
				#elif defined( REINHARD_TONE_MAPPING )
					gl_FragColor.rgb = ReinhardToneMapping( gl_FragColor.rgb );
				#elif defined( CINEON_TONE_MAPPING )
					gl_FragColor.rgb = CineonToneMapping( gl_FragColor.rgb );
				#elif defined( ACES_FILMIC_TONE_MAPPING )
					gl_FragColor.rgb = ACESFilmicToneMapping( gl_FragColor.rgb );
				#elif defined( AGX_TONE_MAPPING )
					gl_FragColor.rgb = AgXToneMapping( gl_FragColor.rgb );
				#elif defined( NEUTRAL_TONE_MAPPING )
					gl_FragColor.rgb = NeutralToneMapping( gl_FragColor.rgb );
				#elif defined( CUSTOM_TONE_MAPPING )
					gl_FragColor.rgb = CustomToneMapping( gl_FragColor.rgb );
				#endif

				#ifdef SRGB_TRANSFER
					gl_FragColor = sRGBTransferOETF( gl_FragColor );
				#endif
			}`,depthTest:!1,depthWrite:!1}),d=new nn(h,u),f=new _r(-1,1,1,-1,0,1),x=null,v=null,m=!1,g,y=null,w=[],p=!1;this.setSize=function(_,S){r.setSize(_,S),o!==null&&o.setSize(_,S),c!==null&&c.setSize(_,S);for(let b=0;b<w.length;b++){let M=w[b];M.setSize&&M.setSize(_,S)}},this.setEffects=function(_){w=_,p=w.length>0&&w[0].isRenderPass===!0;let S=r.width,b=r.height;w.length>0&&o===null&&(o=new Nn(S,b,{type:Zn,depthBuffer:!1,stencilBuffer:!1}),c=new Nn(S,b,{type:Zn,depthBuffer:!1,stencilBuffer:!1}));let M=a===!0&&w.some(E=>E.needsDepthTexture===!0);M!==(r.depthTexture!==null)&&(M===!0&&l===null&&(l=new Ci(S,b),s===!0&&(l.format=Pi,l.type=Ma)),r.dispose(),r.depthTexture=M?l:null,r.resolveDepthBuffer=M,r.storeMultisampledDepthBuffer=M);for(let E=0;E<w.length;E++){let A=w[E];A.setSize&&A.setSize(S,b),M&&A.needsDepthTexture===!0&&A.setDepthTexture&&A.setDepthTexture(l)}},this.begin=function(_,S){if(m||_.toneMapping===li&&w.length===0)return!1;if(y=S,S!==null){let b=S.width,M=S.height;(r.width!==b||r.height!==M)&&this.setSize(b,M)}return p===!1&&_.setRenderTarget(r),g=_.toneMapping,_.toneMapping=li,!0},this.hasRenderPass=function(){return p},this.end=function(_,S){_.toneMapping=g,m=!0;let b=r,M=o;for(let E=0;E<w.length;E++){let A=w[E];A.enabled!==!1&&(A.render(_,M,b,S),A.needsSwap!==!1&&(b=M,M=M===o?c:o))}if(x!==_.outputColorSpace||v!==_.toneMapping){x=_.outputColorSpace,v=_.toneMapping,u.defines={},Kt.getTransfer(x)===pe&&(u.defines.SRGB_TRANSFER="");let E=Ty[v];E&&(u.defines[E]=""),u.needsUpdate=!0}u.uniforms.tDiffuse.value=b.texture,_.setRenderTarget(y),_.render(d,f),y=null,m=!1},this.isCompositing=function(){return m},this.dispose=function(){r.dispose(),o!==null&&o.dispose(),c!==null&&c.dispose(),h.dispose(),u.dispose()}}function ms(i,t,e){let n=i[0];if(n<=0||n>0)return i;let a=t*e,s=Xf[a];if(s===void 0&&(s=new Float32Array(a),Xf[a]=s),t!==0){n.toArray(s,0);for(let r=1,o=0;r!==t;++r)o+=e,i[r].toArray(s,o)}return s}function Be(i,t){if(i.length!==t.length)return!1;for(let e=0,n=i.length;e<n;e++)if(i[e]!==t[e])return!1;return!0}function ke(i,t){for(let e=0,n=t.length;e<n;e++)i[e]=t[e]}function al(i,t){let e=qf[t];e===void 0&&(e=new Int32Array(t),qf[t]=e);for(let n=0;n!==t;++n)e[n]=i.allocateTextureUnit();return e}function Ry(i,t){let e=this.cache;e[0]!==t&&(i.uniform1f(this.addr,t),e[0]=t)}function Cy(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(i.uniform2f(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(Be(e,t))return;i.uniform2fv(this.addr,t),ke(e,t)}}function Ny(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(i.uniform3f(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else if(t.r!==void 0)(e[0]!==t.r||e[1]!==t.g||e[2]!==t.b)&&(i.uniform3f(this.addr,t.r,t.g,t.b),e[0]=t.r,e[1]=t.g,e[2]=t.b);else{if(Be(e,t))return;i.uniform3fv(this.addr,t),ke(e,t)}}function Py(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(i.uniform4f(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(Be(e,t))return;i.uniform4fv(this.addr,t),ke(e,t)}}function Ly(i,t){let e=this.cache,n=t.elements;if(n===void 0){if(Be(e,t))return;i.uniformMatrix2fv(this.addr,!1,t),ke(e,t)}else{if(Be(e,n))return;Kf.set(n),i.uniformMatrix2fv(this.addr,!1,Kf),ke(e,n)}}function Dy(i,t){let e=this.cache,n=t.elements;if(n===void 0){if(Be(e,t))return;i.uniformMatrix3fv(this.addr,!1,t),ke(e,t)}else{if(Be(e,n))return;Jf.set(n),i.uniformMatrix3fv(this.addr,!1,Jf),ke(e,n)}}function Uy(i,t){let e=this.cache,n=t.elements;if(n===void 0){if(Be(e,t))return;i.uniformMatrix4fv(this.addr,!1,t),ke(e,t)}else{if(Be(e,n))return;Yf.set(n),i.uniformMatrix4fv(this.addr,!1,Yf),ke(e,n)}}function Oy(i,t){let e=this.cache;e[0]!==t&&(i.uniform1i(this.addr,t),e[0]=t)}function Fy(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(i.uniform2i(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(Be(e,t))return;i.uniform2iv(this.addr,t),ke(e,t)}}function By(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(i.uniform3i(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else{if(Be(e,t))return;i.uniform3iv(this.addr,t),ke(e,t)}}function ky(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(i.uniform4i(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(Be(e,t))return;i.uniform4iv(this.addr,t),ke(e,t)}}function zy(i,t){let e=this.cache;e[0]!==t&&(i.uniform1ui(this.addr,t),e[0]=t)}function Vy(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y)&&(i.uniform2ui(this.addr,t.x,t.y),e[0]=t.x,e[1]=t.y);else{if(Be(e,t))return;i.uniform2uiv(this.addr,t),ke(e,t)}}function Hy(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z)&&(i.uniform3ui(this.addr,t.x,t.y,t.z),e[0]=t.x,e[1]=t.y,e[2]=t.z);else{if(Be(e,t))return;i.uniform3uiv(this.addr,t),ke(e,t)}}function Gy(i,t){let e=this.cache;if(t.x!==void 0)(e[0]!==t.x||e[1]!==t.y||e[2]!==t.z||e[3]!==t.w)&&(i.uniform4ui(this.addr,t.x,t.y,t.z,t.w),e[0]=t.x,e[1]=t.y,e[2]=t.z,e[3]=t.w);else{if(Be(e,t))return;i.uniform4uiv(this.addr,t),ke(e,t)}}function sl(i){return i.version===0&&(i.compareFunction=Jh,i.needsUpdate=!0),i}function Wy(i,t,e){let n=this.cache,a=e.allocateTextureUnit();n[0]!==a&&(i.uniform1i(this.addr,a),n[0]=a);let s;this.type===i.SAMPLER_2D_SHADOW?s=sl(pp):s=fp,e.setTexture2D(t||s,a)}function jy(i,t,e){let n=this.cache,a=e.allocateTextureUnit();n[0]!==a&&(i.uniform1i(this.addr,a),n[0]=a),e.setTexture3D(t||bp,a)}function Xy(i,t,e){let n=this.cache,a=e.allocateTextureUnit();n[0]!==a&&(i.uniform1i(this.addr,a),n[0]=a);let s;this.type===i.SAMPLER_CUBE_SHADOW?s=sl(mp):s=xp,e.setTextureCube(t||s,a)}function qy(i,t,e){let n=this.cache,a=e.allocateTextureUnit();n[0]!==a&&(i.uniform1i(this.addr,a),n[0]=a),e.setTexture2DArray(t||gp,a)}function Yy(i){switch(i){case 5126:return Ry;case 35664:return Cy;case 35665:return Ny;case 35666:return Py;case 35674:return Ly;case 35675:return Dy;case 35676:return Uy;case 5124:case 35670:return Oy;case 35667:case 35671:return Fy;case 35668:case 35672:return By;case 35669:case 35673:return ky;case 5125:return zy;case 36294:return Vy;case 36295:return Hy;case 36296:return Gy;case 35678:case 36198:case 36298:case 36306:case 35682:return Wy;case 35679:case 36299:case 36307:return jy;case 35680:case 36300:case 36308:case 36293:return Xy;case 36289:case 36303:case 36311:case 36292:return qy}}function Jy(i,t){i.uniform1fv(this.addr,t)}function Ky(i,t){let e=ms(t,this.size,2);i.uniform2fv(this.addr,e)}function Zy(i,t){let e=ms(t,this.size,3);i.uniform3fv(this.addr,e)}function Qy(i,t){let e=ms(t,this.size,4);i.uniform4fv(this.addr,e)}function $y(i,t){let e=ms(t,this.size,4);i.uniformMatrix2fv(this.addr,!1,e)}function t_(i,t){let e=ms(t,this.size,9);i.uniformMatrix3fv(this.addr,!1,e)}function e_(i,t){let e=ms(t,this.size,16);i.uniformMatrix4fv(this.addr,!1,e)}function n_(i,t){i.uniform1iv(this.addr,t)}function i_(i,t){i.uniform2iv(this.addr,t)}function a_(i,t){i.uniform3iv(this.addr,t)}function s_(i,t){i.uniform4iv(this.addr,t)}function r_(i,t){i.uniform1uiv(this.addr,t)}function o_(i,t){i.uniform2uiv(this.addr,t)}function c_(i,t){i.uniform3uiv(this.addr,t)}function l_(i,t){i.uniform4uiv(this.addr,t)}function h_(i,t,e){let n=this.cache,a=t.length,s=al(e,a);Be(n,s)||(i.uniform1iv(this.addr,s),ke(n,s));let r;this.type===i.SAMPLER_2D_SHADOW?r=sl(pp):r=fp;for(let o=0;o!==a;++o)e.setTexture2D(t[o]||r,s[o])}function d_(i,t,e){let n=this.cache,a=t.length,s=al(e,a);Be(n,s)||(i.uniform1iv(this.addr,s),ke(n,s));for(let r=0;r!==a;++r)e.setTexture3D(t[r]||bp,s[r])}function u_(i,t,e){let n=this.cache,a=t.length,s=al(e,a);Be(n,s)||(i.uniform1iv(this.addr,s),ke(n,s));let r;this.type===i.SAMPLER_CUBE_SHADOW?r=sl(mp):r=xp;for(let o=0;o!==a;++o)e.setTextureCube(t[o]||r,s[o])}function f_(i,t,e){let n=this.cache,a=t.length,s=al(e,a);Be(n,s)||(i.uniform1iv(this.addr,s),ke(n,s));for(let r=0;r!==a;++r)e.setTexture2DArray(t[r]||gp,s[r])}function p_(i){switch(i){case 5126:return Jy;case 35664:return Ky;case 35665:return Zy;case 35666:return Qy;case 35674:return $y;case 35675:return t_;case 35676:return e_;case 5124:case 35670:return n_;case 35667:case 35671:return i_;case 35668:case 35672:return a_;case 35669:case 35673:return s_;case 5125:return r_;case 36294:return o_;case 36295:return c_;case 36296:return l_;case 35678:case 36198:case 36298:case 36306:case 35682:return h_;case 35679:case 36299:case 36307:return d_;case 35680:case 36300:case 36308:case 36293:return u_;case 36289:case 36303:case 36311:case 36292:return f_}}function Zf(i,t){i.seq.push(t),i.map[t.id]=t}function m_(i,t,e){let n=i.name,a=n.length;for(ud.lastIndex=0;;){let s=ud.exec(n),r=ud.lastIndex,o=s[1],c=s[2]==="]",l=s[3];if(c&&(o=o|0),l===void 0||l==="["&&r+2===a){Zf(e,l===void 0?new pd(o,i,t):new md(o,i,t));break}else{let u=e.map[o];u===void 0&&(u=new gd(o),Zf(e,u)),e=u}}}function Qf(i,t,e){let n=i.createShader(t);return i.shaderSource(n,e),i.compileShader(n),n}function x_(i,t){let e=i.split(`
`),n=[],a=Math.max(t-6,0),s=Math.min(t+6,e.length);for(let r=a;r<s;r++){let o=r+1;n.push(`${o===t?">":" "} ${o}: ${e[r]}`)}return n.join(`
`)}function y_(i){Kt._getMatrix($f,Kt.workingColorSpace,i);let t=`mat3( ${$f.elements.map(e=>e.toFixed(4))} )`;switch(Kt.getTransfer(i)){case Zs:return[t,"LinearTransferOETF"];case pe:return[t,"sRGBTransferOETF"];default:return Ft("WebGLProgram: Unsupported color space: ",i),[t,"LinearTransferOETF"]}}function tp(i,t,e){let n=i.getShaderParameter(t,i.COMPILE_STATUS),s=(i.getShaderInfoLog(t)||"").trim();if(n&&s==="")return"";let r=/ERROR: 0:(\d+)/.exec(s);if(r){let o=parseInt(r[1]);return e.toUpperCase()+`

`+s+`

`+x_(i.getShaderSource(t),o)}else return s}function __(i,t){let e=y_(t);return[`vec4 ${i}( vec4 value ) {`,`	return ${e[1]}( vec4( ${e[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}function M_(i,t){let e=v_[t];return e===void 0?(Ft("WebGLProgram: Unsupported toneMapping:",t),"vec3 "+i+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+i+"( vec3 color ) { return "+e+"ToneMapping( color ); }"}function S_(){Kt.getLuminanceCoefficients(el);let i=el.x.toFixed(4),t=el.y.toFixed(4),e=el.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${i}, ${t}, ${e} );`,"	return dot( weights, rgb );","}"].join(`
`)}function w_(i){return[i.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",i.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(zr).join(`
`)}function A_(i){let t=[];for(let e in i){let n=i[e];n!==!1&&t.push("#define "+e+" "+n)}return t.join(`
`)}function E_(i,t){let e={},n=i.getProgramParameter(t,i.ACTIVE_ATTRIBUTES);for(let a=0;a<n;a++){let s=i.getActiveAttrib(t,a),r=s.name,o=1;s.type===i.FLOAT_MAT2&&(o=2),s.type===i.FLOAT_MAT3&&(o=3),s.type===i.FLOAT_MAT4&&(o=4),e[r]={type:s.type,location:i.getAttribLocation(t,r),locationSize:o}}return e}function zr(i){return i!==""}function ep(i,t){let e=t.numSpotLightShadows+t.numSpotLightMaps-t.numSpotLightShadowsWithMaps;return i.replace(/NUM_SUN_LIGHTS/g,t.numSunLights).replace(/NUM_DIR_LIGHTS/g,t.numDirLights).replace(/NUM_SPOT_LIGHTS/g,t.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,t.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,e).replace(/NUM_RECT_AREA_LIGHTS/g,t.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,t.numPointLights).replace(/NUM_HEMI_LIGHTS/g,t.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,t.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,t.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,t.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,t.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,t.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,t.numLightProbeGrids)}function np(i,t){return i.replace(/NUM_CLIPPING_PLANES/g,t.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,t.numClippingPlanes-t.numClipIntersection)}function bd(i){return i.replace(T_,I_)}function I_(i,t){let e=qt[t];if(e===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+t+">");return bd(e)}function ip(i){return i.replace(R_,C_)}function C_(i,t,e,n){let a="";for(let s=parseInt(t);s<parseInt(e);s++)a+=n.replace(/\[\s*i\s*\]/g,"[ "+s+" ]").replace(/UNROLLED_LOOP_INDEX/g,s);return a}function ap(i){let t=`precision ${i.precision} float;
	precision ${i.precision} int;
	precision ${i.precision} sampler2D;
	precision ${i.precision} samplerCube;
	precision ${i.precision} sampler3D;
	precision ${i.precision} sampler2DArray;
	precision ${i.precision} sampler2DShadow;
	precision ${i.precision} samplerCubeShadow;
	precision ${i.precision} sampler2DArrayShadow;
	precision ${i.precision} isampler2D;
	precision ${i.precision} isampler3D;
	precision ${i.precision} isamplerCube;
	precision ${i.precision} isampler2DArray;
	precision ${i.precision} usampler2D;
	precision ${i.precision} usampler3D;
	precision ${i.precision} usamplerCube;
	precision ${i.precision} usampler2DArray;
	`;return i.precision==="highp"?t+=`
#define HIGH_PRECISION`:i.precision==="mediump"?t+=`
#define MEDIUM_PRECISION`:i.precision==="lowp"&&(t+=`
#define LOW_PRECISION`),t}function P_(i){return N_[i.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}function D_(i){return i.envMap===!1?"ENVMAP_MODE_REFLECTION":L_[i.envMapMode]||"ENVMAP_MODE_REFLECTION"}function O_(i){return i.envMap===!1?"ENVMAP_BLENDING_NONE":U_[i.combine]||"ENVMAP_BLENDING_NONE"}function F_(i,t,e,n){let a=i.getContext(),s=e.defines,r=e.vertexShader,o=e.fragmentShader,c=P_(e),l=e.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",h=D_(e),u=O_(e),d=w_(e),f=A_(s),x=a.createProgram(),v,m,g=e.glslVersion?"#version "+e.glslVersion+`
`:"";e.isRawShaderMaterial?(v=["#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,f].filter(zr).join(`
`),v.length>0&&(v+=`
`),m=["#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,f].filter(zr).join(`
`),m.length>0&&(m+=`
`)):(v=[ap(e),"#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,f,e.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",e.batching?"#define USE_BATCHING":"",e.batchingColor?"#define USE_BATCHING_COLOR":"",e.instancing?"#define USE_INSTANCING":"",e.instancingColor?"#define USE_INSTANCING_COLOR":"",e.instancingMorph?"#define USE_INSTANCING_MORPH":"",e.useFog&&e.fog?"#define USE_FOG":"",e.useFog&&e.fogExp2?"#define FOG_EXP2":"",e.map?"#define USE_MAP":"",e.envMap?"#define USE_ENVMAP":"",e.envMap?"#define "+h:"",e.lightMap?"#define USE_LIGHTMAP":"",e.aoMap?"#define USE_AOMAP":"",e.bumpMap?"#define USE_BUMPMAP":"",e.normalMap?"#define USE_NORMALMAP":"",e.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",e.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",e.displacementMap?"#define USE_DISPLACEMENTMAP":"",e.emissiveMap?"#define USE_EMISSIVEMAP":"",e.anisotropy?"#define USE_ANISOTROPY":"",e.anisotropyMap?"#define USE_ANISOTROPYMAP":"",e.clearcoatMap?"#define USE_CLEARCOATMAP":"",e.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",e.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",e.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",e.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",e.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",e.specularMap?"#define USE_SPECULARMAP":"",e.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",e.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",e.roughnessMap?"#define USE_ROUGHNESSMAP":"",e.metalnessMap?"#define USE_METALNESSMAP":"",e.alphaMap?"#define USE_ALPHAMAP":"",e.alphaHash?"#define USE_ALPHAHASH":"",e.transmission?"#define USE_TRANSMISSION":"",e.transmissionMap?"#define USE_TRANSMISSIONMAP":"",e.thicknessMap?"#define USE_THICKNESSMAP":"",e.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",e.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",e.mapUv?"#define MAP_UV "+e.mapUv:"",e.alphaMapUv?"#define ALPHAMAP_UV "+e.alphaMapUv:"",e.lightMapUv?"#define LIGHTMAP_UV "+e.lightMapUv:"",e.aoMapUv?"#define AOMAP_UV "+e.aoMapUv:"",e.emissiveMapUv?"#define EMISSIVEMAP_UV "+e.emissiveMapUv:"",e.bumpMapUv?"#define BUMPMAP_UV "+e.bumpMapUv:"",e.normalMapUv?"#define NORMALMAP_UV "+e.normalMapUv:"",e.displacementMapUv?"#define DISPLACEMENTMAP_UV "+e.displacementMapUv:"",e.metalnessMapUv?"#define METALNESSMAP_UV "+e.metalnessMapUv:"",e.roughnessMapUv?"#define ROUGHNESSMAP_UV "+e.roughnessMapUv:"",e.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+e.anisotropyMapUv:"",e.clearcoatMapUv?"#define CLEARCOATMAP_UV "+e.clearcoatMapUv:"",e.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+e.clearcoatNormalMapUv:"",e.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+e.clearcoatRoughnessMapUv:"",e.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+e.diffuseRoughnessMapUv:"",e.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+e.iridescenceMapUv:"",e.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+e.iridescenceThicknessMapUv:"",e.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+e.sheenColorMapUv:"",e.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+e.sheenRoughnessMapUv:"",e.specularMapUv?"#define SPECULARMAP_UV "+e.specularMapUv:"",e.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+e.specularColorMapUv:"",e.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+e.specularIntensityMapUv:"",e.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+e.transmissionMapUv:"",e.thicknessMapUv?"#define THICKNESSMAP_UV "+e.thicknessMapUv:"",e.vertexTangents&&e.flatShading===!1?"#define USE_TANGENT":"",e.vertexNormals?"#define HAS_NORMAL":"",e.vertexColors?"#define USE_COLOR":"",e.vertexAlphas?"#define USE_COLOR_ALPHA":"",e.vertexUv1s?"#define USE_UV1":"",e.vertexUv2s?"#define USE_UV2":"",e.vertexUv3s?"#define USE_UV3":"",e.pointsUvs?"#define USE_POINTS_UV":"",e.flatShading?"#define FLAT_SHADED":"",e.skinning?"#define USE_SKINNING":"",e.morphTargets?"#define USE_MORPHTARGETS":"",e.morphNormals&&e.flatShading===!1?"#define USE_MORPHNORMALS":"",e.morphColors?"#define USE_MORPHCOLORS":"",e.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+e.morphTextureStride:"",e.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+e.morphTargetsCount:"",e.doubleSided?"#define DOUBLE_SIDED":"",e.flipSided?"#define FLIP_SIDED":"",e.shadowMapEnabled?"#define USE_SHADOWMAP":"",e.shadowMapEnabled?"#define "+c:"",e.sizeAttenuation?"#define USE_SIZEATTENUATION":"",e.numLightProbes>0?"#define USE_LIGHT_PROBES":"",e.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",e.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(zr).join(`
`),m=[ap(e),"#define SHADER_TYPE "+e.shaderType,"#define SHADER_NAME "+e.shaderName,f,e.useFog&&e.fog?"#define USE_FOG":"",e.useFog&&e.fogExp2?"#define FOG_EXP2":"",e.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",e.map?"#define USE_MAP":"",e.matcap?"#define USE_MATCAP":"",e.envMap?"#define USE_ENVMAP":"",e.envMap?"#define "+l:"",e.envMap?"#define "+h:"",e.envMap?"#define "+u:"",e.envMapPMREM?"#define ENVMAP_MAX_LOD "+e.envMapMaxLod+".0":"",e.envMapPMREM?"#define ENVMAP_SIZE "+e.envMapSize+".0":"",e.lightMap?"#define USE_LIGHTMAP":"",e.aoMap?"#define USE_AOMAP":"",e.bumpMap?"#define USE_BUMPMAP":"",e.normalMap?"#define USE_NORMALMAP":"",e.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",e.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",e.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",e.emissiveMap?"#define USE_EMISSIVEMAP":"",e.anisotropy?"#define USE_ANISOTROPY":"",e.anisotropyMap?"#define USE_ANISOTROPYMAP":"",e.clearcoat?"#define USE_CLEARCOAT":"",e.clearcoatMap?"#define USE_CLEARCOATMAP":"",e.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",e.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",e.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",e.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",e.dispersion?"#define USE_DISPERSION":"",e.retroreflection?"#define USE_RETROREFLECTION":"",e.iridescence?"#define USE_IRIDESCENCE":"",e.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",e.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",e.specularMap?"#define USE_SPECULARMAP":"",e.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",e.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",e.roughnessMap?"#define USE_ROUGHNESSMAP":"",e.metalnessMap?"#define USE_METALNESSMAP":"",e.alphaMap?"#define USE_ALPHAMAP":"",e.alphaTest?"#define USE_ALPHATEST":"",e.alphaHash?"#define USE_ALPHAHASH":"",e.sheen?"#define USE_SHEEN":"",e.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",e.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",e.transmission?"#define USE_TRANSMISSION":"",e.transmissionMap?"#define USE_TRANSMISSIONMAP":"",e.thicknessMap?"#define USE_THICKNESSMAP":"",e.vertexTangents&&e.flatShading===!1?"#define USE_TANGENT":"",e.vertexColors||e.instancingColor?"#define USE_COLOR":"",e.vertexAlphas||e.batchingColor?"#define USE_COLOR_ALPHA":"",e.vertexUv1s?"#define USE_UV1":"",e.vertexUv2s?"#define USE_UV2":"",e.vertexUv3s?"#define USE_UV3":"",e.pointsUvs?"#define USE_POINTS_UV":"",e.gradientMap?"#define USE_GRADIENTMAP":"",e.flatShading?"#define FLAT_SHADED":"",e.doubleSided?"#define DOUBLE_SIDED":"",e.flipSided?"#define FLIP_SIDED":"",e.shadowMapEnabled?"#define USE_SHADOWMAP":"",e.shadowMapEnabled?"#define "+c:"",e.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",e.numLightProbes>0?"#define USE_LIGHT_PROBES":"",e.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",e.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",e.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",e.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",e.toneMapping!==li?"#define TONE_MAPPING":"",e.toneMapping!==li?qt.tonemapping_pars_fragment:"",e.toneMapping!==li?M_("toneMapping",e.toneMapping):"",e.dithering?"#define DITHERING":"",e.opaque?"#define OPAQUE":"",qt.colorspace_pars_fragment,__("linearToOutputTexel",e.outputColorSpace),S_(),e.useDepthPacking?"#define DEPTH_PACKING "+e.depthPacking:"",`
`].filter(zr).join(`
`)),r=bd(r),r=ep(r,e),r=np(r,e),o=bd(o),o=ep(o,e),o=np(o,e),r=ip(r),o=ip(o),e.isRawShaderMaterial!==!0&&(g=`#version 300 es
`,v=[d,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+v,m=["#define varying in",e.glslVersion===Zh?"":"layout(location = 0) out highp vec4 pc_fragColor;",e.glslVersion===Zh?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+m);let y=g+v+r,w=g+m+o,p=Qf(a,a.VERTEX_SHADER,y),_=Qf(a,a.FRAGMENT_SHADER,w);a.attachShader(x,p),a.attachShader(x,_),e.index0AttributeName!==void 0?a.bindAttribLocation(x,0,e.index0AttributeName):e.hasPositionAttribute===!0&&a.bindAttribLocation(x,0,"position"),a.linkProgram(x);function S(A){if(i.debug.checkShaderErrors){let I=a.getProgramInfoLog(x)||"",N=a.getShaderInfoLog(p)||"",L=a.getShaderInfoLog(_)||"",P=I.trim(),U=N.trim(),V=L.trim(),O=!0,Q=!0;if(a.getProgramParameter(x,a.LINK_STATUS)===!1)if(O=!1,typeof i.debug.onShaderError=="function")i.debug.onShaderError(a,x,p,_);else{let G=tp(a,p,"vertex"),Z=tp(a,_,"fragment");zt("WebGLProgram: Shader Error "+a.getError()+" - VALIDATE_STATUS "+a.getProgramParameter(x,a.VALIDATE_STATUS)+`

Material Name: `+A.name+`
Material Type: `+A.type+`

Program Info Log: `+P+`
`+G+`
`+Z)}else P!==""?Ft("WebGLProgram: Program Info Log:",P):(U===""||V==="")&&(Q=!1);Q&&(A.diagnostics={runnable:O,programLog:P,vertexShader:{log:U,prefix:v},fragmentShader:{log:V,prefix:m}})}a.deleteShader(p),a.deleteShader(_),b=new ps(a,x),M=E_(a,x)}let b;this.getUniforms=function(){return b===void 0&&S(this),b};let M;this.getAttributes=function(){return M===void 0&&S(this),M};let E=e.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return E===!1&&(E=a.getProgramParameter(x,g_)),E},this.destroy=function(){n.releaseStatesOfProgram(this),a.deleteProgram(x),this.program=void 0},this.type=e.shaderType,this.name=e.shaderName,this.id=b_++,this.cacheKey=t,this.usedTimes=1,this.program=x,this.vertexShader=p,this.fragmentShader=_,this}function k_(i){return i===hi||i===Or||i===Fr}function z_(i,t,e,n,a,s){let r=new ts,o=new xd,c=new Set,l=[],h=new Map,u=n.logarithmicDepthBuffer,d={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function f(b){return c.add(b),b===0?"uv":`uv${b}`}function x(b,M,E,A,I,N){let L=A.fog,P=I.geometry,U=b.isMeshStandardMaterial||b.isMeshLambertMaterial||b.isMeshPhongMaterial?A.environment:null,V=b.isMeshStandardMaterial||b.isMeshLambertMaterial&&!b.envMap||b.isMeshPhongMaterial&&!b.envMap,O=t.get(b.envMap||U,V),Q=d[b.type],G=n.precision;b.precision!==null&&(G=n.getMaxPrecision(b.precision),G!==b.precision&&Ft("WebGLProgram.getParameters:",b.precision,"not supported, using",G,"instead."));let Z=P.morphAttributes.position||P.morphAttributes.normal||P.morphAttributes.color,et=Z!==void 0?Z.length:0,ht=0;P.morphAttributes.position!==void 0&&(ht=1),P.morphAttributes.normal!==void 0&&(ht=2),P.morphAttributes.color!==void 0&&(ht=3);let Pt,Y,ct,mt;if(Q){let pt=xn[Q];Pt=pt.vertexShader,Y=pt.fragmentShader}else{Pt=b.vertexShader,Y=b.fragmentShader;let pt=o.getVertexShaderStage(b),re=o.getFragmentShaderStage(b);o.update(b,pt,re),ct=pt.id,mt=re.id}let Tt=i.getRenderTarget(),gt=i.state.buffers.depth.getReversed(),Ot=I.isInstancedMesh===!0,ge=I.isBatchedMesh===!0,Dt=!!b.map,kt=!!b.matcap,Yt=!!O,Xt=Yt&&O.isPMREMTexture===!0,Ae=!!b.aoMap,nt=!!b.lightMap,St=!!b.bumpMap&&b.wireframe===!1,wt=!!b.normalMap,Qt=!!b.displacementMap,Ht=!!b.emissiveMap,be=!!b.metalnessMap,fe=!!b.roughnessMap,ne=b.anisotropy>0,B=b.clearcoat>0,Ee=b.diffuseRoughness>0,$t=b.dispersion>0,Jt=b.retroreflectivity>0,dt=b.iridescence>0,se=b.sheen>0,At=b.transmission>0,Lt=ne&&!!b.anisotropyMap,D=B&&!!b.clearcoatMap,T=B&&!!b.clearcoatNormalMap,W=B&&!!b.clearcoatRoughnessMap,at=Ee&&!!b.diffuseRoughnessMap,tt=dt&&!!b.iridescenceMap,lt=dt&&!!b.iridescenceThicknessMap,ut=se&&!!b.sheenColorMap,$=se&&!!b.sheenRoughnessMap,J=!!b.specularMap,ft=!!b.specularColorMap,R=!!b.specularIntensityMap,k=At&&!!b.transmissionMap,H=At&&!!b.thicknessMap,j=!!b.gradientMap,it=!!b.alphaMap,st=b.alphaTest>0,_t=!!b.alphaHash,Ct=!!b.extensions,ot=li;b.toneMapped&&(Tt===null||Tt.isXRRenderTarget===!0)&&(ot=i.toneMapping);let vt=Xt?O.isCompressedCubeTexture?O.image[0].mipmaps:O.mipmaps:null,Ut={shaderID:Q,shaderType:b.type,shaderName:b.name,vertexShader:Pt,fragmentShader:Y,defines:b.defines,customVertexShaderID:ct,customFragmentShaderID:mt,isRawShaderMaterial:b.isRawShaderMaterial===!0,glslVersion:b.glslVersion,precision:G,batching:ge,batchingColor:ge&&I._colorsTexture!==null,instancing:Ot,instancingColor:Ot&&I.instanceColor!==null,instancingMorph:Ot&&I.morphTexture!==null,outputColorSpace:Tt===null?i.outputColorSpace:Tt.isXRRenderTarget===!0?Tt.texture.colorSpace:Kt.workingColorSpace,alphaToCoverage:!!b.alphaToCoverage,map:Dt,matcap:kt,envMap:Yt,envMapMode:Yt&&O.mapping,envMapPMREM:Xt,envMapMaxLod:Xt?vt.length-1:null,envMapSize:Xt?vt[0].width:null,aoMap:Ae,lightMap:nt,bumpMap:St,normalMap:wt,displacementMap:Qt,emissiveMap:Ht,normalMapObjectSpace:wt&&b.normalMapType===If,normalMapTangentSpace:wt&&b.normalMapType===Qc,packedNormalMap:wt&&b.normalMapType===Qc&&k_(b.normalMap.format),metalnessMap:be,roughnessMap:fe,anisotropy:ne,anisotropyMap:Lt,clearcoat:B,clearcoatMap:D,clearcoatNormalMap:T,clearcoatRoughnessMap:W,diffuseRoughness:Ee,diffuseRoughnessMap:at,dispersion:$t,retroreflection:Jt,iridescence:dt,iridescenceMap:tt,iridescenceThicknessMap:lt,sheen:se,sheenColorMap:ut,sheenRoughnessMap:$,specularMap:J,specularColorMap:ft,specularIntensityMap:R,transmission:At,transmissionMap:k,thicknessMap:H,gradientMap:j,opaque:b.transparent===!1&&b.blending===ls&&b.alphaToCoverage===!1,alphaMap:it,alphaTest:st,alphaHash:_t,combine:b.combine,mapUv:Dt&&f(b.map.channel),aoMapUv:Ae&&f(b.aoMap.channel),lightMapUv:nt&&f(b.lightMap.channel),bumpMapUv:St&&f(b.bumpMap.channel),normalMapUv:wt&&f(b.normalMap.channel),displacementMapUv:Qt&&f(b.displacementMap.channel),emissiveMapUv:Ht&&f(b.emissiveMap.channel),metalnessMapUv:be&&f(b.metalnessMap.channel),roughnessMapUv:fe&&f(b.roughnessMap.channel),anisotropyMapUv:Lt&&f(b.anisotropyMap.channel),clearcoatMapUv:D&&f(b.clearcoatMap.channel),clearcoatNormalMapUv:T&&f(b.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:W&&f(b.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:at&&f(b.diffuseRoughnessMap.channel),iridescenceMapUv:tt&&f(b.iridescenceMap.channel),iridescenceThicknessMapUv:lt&&f(b.iridescenceThicknessMap.channel),sheenColorMapUv:ut&&f(b.sheenColorMap.channel),sheenRoughnessMapUv:$&&f(b.sheenRoughnessMap.channel),specularMapUv:J&&f(b.specularMap.channel),specularColorMapUv:ft&&f(b.specularColorMap.channel),specularIntensityMapUv:R&&f(b.specularIntensityMap.channel),transmissionMapUv:k&&f(b.transmissionMap.channel),thicknessMapUv:H&&f(b.thicknessMap.channel),alphaMapUv:it&&f(b.alphaMap.channel),vertexTangents:!!P.attributes.tangent&&(wt||ne),vertexNormals:!!P.attributes.normal,vertexColors:b.vertexColors,vertexAlphas:b.vertexColors===!0&&!!P.attributes.color&&P.attributes.color.itemSize===4,pointsUvs:I.isPoints===!0&&!!P.attributes.uv&&(Dt||it),fog:!!L,useFog:b.fog===!0,fogExp2:!!L&&L.isFogExp2,flatShading:b.wireframe===!1&&(b.flatShading===!0||P.attributes.normal===void 0&&wt===!1&&(b.isMeshLambertMaterial||b.isMeshPhongMaterial||b.isMeshStandardMaterial||b.isMeshPhysicalMaterial)),sizeAttenuation:b.sizeAttenuation===!0,logarithmicDepthBuffer:u,reversedDepthBuffer:gt,skinning:I.isSkinnedMesh===!0,hasPositionAttribute:P.attributes.position!==void 0,morphTargets:P.morphAttributes.position!==void 0,morphNormals:P.morphAttributes.normal!==void 0,morphColors:P.morphAttributes.color!==void 0,morphTargetsCount:et,morphTextureStride:ht,numSunLights:M.sun.length,numDirLights:M.directional.length,numPointLights:M.point.length,numSpotLights:M.spot.length,numSpotLightMaps:M.spotLightMap.length,numRectAreaLights:M.rectArea.length,numHemiLights:M.hemi.length,numSunLightShadows:M.sunShadowMap.length,numDirLightShadows:M.directionalShadowMap.length,numPointLightShadows:M.pointShadowMap.length,numSpotLightShadows:M.spotShadowMap.length,numSpotLightShadowsWithMaps:M.numSpotLightShadowsWithMaps,numLightProbes:M.numLightProbes,numLightProbeGrids:N.filter(pt=>pt.texture!==null).length,numClippingPlanes:s.numPlanes,numClipIntersection:s.numIntersection,dithering:b.dithering,shadowMapEnabled:i.shadowMap.enabled&&E.length>0,shadowMapType:i.shadowMap.type,toneMapping:ot,decodeVideoTexture:Dt&&b.map.isVideoTexture===!0&&Kt.getTransfer(b.map.colorSpace)===pe,decodeVideoTextureEmissive:Ht&&b.emissiveMap.isVideoTexture===!0&&Kt.getTransfer(b.emissiveMap.colorSpace)===pe,premultipliedAlpha:b.premultipliedAlpha,doubleSided:b.side===kn,flipSided:b.side===je,useDepthPacking:b.depthPacking>=0,depthPacking:b.depthPacking||0,index0AttributeName:b.index0AttributeName,extensionClipCullDistance:Ct&&b.extensions.clipCullDistance===!0&&e.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(Ct&&b.extensions.multiDraw===!0||ge)&&e.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:e.has("KHR_parallel_shader_compile"),customProgramCacheKey:b.customProgramCacheKey()};return Ut.vertexUv1s=c.has(1),Ut.vertexUv2s=c.has(2),Ut.vertexUv3s=c.has(3),c.clear(),Ut}function v(b){let M=[];if(b.shaderID?M.push(b.shaderID):(M.push(b.customVertexShaderID),M.push(b.customFragmentShaderID)),b.defines!==void 0)for(let E in b.defines)M.push(E),M.push(b.defines[E]);return b.isRawShaderMaterial===!1&&(m(M,b),g(M,b),M.push(i.outputColorSpace)),M.push(b.customProgramCacheKey),M.join()}function m(b,M){b.push(M.precision),b.push(M.outputColorSpace),b.push(M.envMapMode),b.push(M.envMapPMREM),b.push(M.envMapMaxLod),b.push(M.envMapSize),b.push(M.mapUv),b.push(M.alphaMapUv),b.push(M.lightMapUv),b.push(M.aoMapUv),b.push(M.bumpMapUv),b.push(M.normalMapUv),b.push(M.displacementMapUv),b.push(M.emissiveMapUv),b.push(M.metalnessMapUv),b.push(M.roughnessMapUv),b.push(M.anisotropyMapUv),b.push(M.clearcoatMapUv),b.push(M.clearcoatNormalMapUv),b.push(M.clearcoatRoughnessMapUv),b.push(M.diffuseRoughnessMapUv),b.push(M.iridescenceMapUv),b.push(M.iridescenceThicknessMapUv),b.push(M.sheenColorMapUv),b.push(M.sheenRoughnessMapUv),b.push(M.specularMapUv),b.push(M.specularColorMapUv),b.push(M.specularIntensityMapUv),b.push(M.transmissionMapUv),b.push(M.thicknessMapUv),b.push(M.combine),b.push(M.fogExp2),b.push(M.sizeAttenuation),b.push(M.morphTargetsCount),b.push(M.numSunLights),b.push(M.numDirLights),b.push(M.numPointLights),b.push(M.numSpotLights),b.push(M.numSpotLightMaps),b.push(M.numHemiLights),b.push(M.numRectAreaLights),b.push(M.numSunLightShadows),b.push(M.numDirLightShadows),b.push(M.numPointLightShadows),b.push(M.numSpotLightShadows),b.push(M.numSpotLightShadowsWithMaps),b.push(M.numLightProbes),b.push(M.numLightProbeGrids),b.push(M.shadowMapType),b.push(M.toneMapping),b.push(M.numClippingPlanes),b.push(M.numClipIntersection),b.push(M.depthPacking)}function g(b,M){r.disableAll(),M.instancing&&r.enable(0),M.instancingColor&&r.enable(1),M.instancingMorph&&r.enable(2),M.matcap&&r.enable(3),M.envMap&&r.enable(4),M.normalMapObjectSpace&&r.enable(5),M.normalMapTangentSpace&&r.enable(6),M.clearcoat&&r.enable(7),M.iridescence&&r.enable(8),M.alphaTest&&r.enable(9),M.vertexColors&&r.enable(10),M.vertexAlphas&&r.enable(11),M.vertexUv1s&&r.enable(12),M.vertexUv2s&&r.enable(13),M.vertexUv3s&&r.enable(14),M.vertexTangents&&r.enable(15),M.anisotropy&&r.enable(16),M.alphaHash&&r.enable(17),M.batching&&r.enable(18),M.dispersion&&r.enable(19),M.retroreflection&&r.enable(24),M.diffuseRoughness&&r.enable(25),M.batchingColor&&r.enable(20),M.gradientMap&&r.enable(21),M.packedNormalMap&&r.enable(22),M.vertexNormals&&r.enable(23),b.push(r.mask),r.disableAll(),M.fog&&r.enable(0),M.useFog&&r.enable(1),M.flatShading&&r.enable(2),M.logarithmicDepthBuffer&&r.enable(3),M.reversedDepthBuffer&&r.enable(4),M.skinning&&r.enable(5),M.morphTargets&&r.enable(6),M.morphNormals&&r.enable(7),M.morphColors&&r.enable(8),M.premultipliedAlpha&&r.enable(9),M.shadowMapEnabled&&r.enable(10),M.doubleSided&&r.enable(11),M.flipSided&&r.enable(12),M.useDepthPacking&&r.enable(13),M.dithering&&r.enable(14),M.transmission&&r.enable(15),M.sheen&&r.enable(16),M.opaque&&r.enable(17),M.pointsUvs&&r.enable(18),M.decodeVideoTexture&&r.enable(19),M.decodeVideoTextureEmissive&&r.enable(20),M.alphaToCoverage&&r.enable(21),M.numLightProbeGrids>0&&r.enable(22),M.hasPositionAttribute&&r.enable(23),b.push(r.mask)}function y(b){let M=d[b.type],E;if(M){let A=xn[M];E=Br.clone(A.uniforms)}else E=b.uniforms;return E}function w(b,M){let E=h.get(M);return E!==void 0?++E.usedTimes:(E=new F_(i,M,b,a),l.push(E),h.set(M,E)),E}function p(b){if(--b.usedTimes===0){let M=l.indexOf(b);l[M]=l[l.length-1],l.pop(),h.delete(b.cacheKey),b.destroy()}}function _(b){o.remove(b)}function S(){o.dispose()}return{getParameters:x,getProgramCacheKey:v,getUniforms:y,acquireProgram:w,releaseProgram:p,releaseShaderCache:_,programs:l,dispose:S}}function V_(){let i=new WeakMap;function t(r){return i.has(r)}function e(r){let o=i.get(r);return o===void 0&&(o={},i.set(r,o)),o}function n(r){i.delete(r)}function a(r,o,c){i.get(r)[o]=c}function s(){i=new WeakMap}return{has:t,get:e,remove:n,update:a,dispose:s}}function H_(i,t){return i.groupOrder!==t.groupOrder?i.groupOrder-t.groupOrder:i.renderOrder!==t.renderOrder?i.renderOrder-t.renderOrder:i.material.id!==t.material.id?i.material.id-t.material.id:i.materialVariant!==t.materialVariant?i.materialVariant-t.materialVariant:i.z!==t.z?i.z-t.z:i.id-t.id}function sp(i,t){return i.groupOrder!==t.groupOrder?i.groupOrder-t.groupOrder:i.renderOrder!==t.renderOrder?i.renderOrder-t.renderOrder:i.z!==t.z?t.z-i.z:i.id-t.id}function rp(){let i=[],t=0,e=[],n=[],a=[];function s(){t=0,e.length=0,n.length=0,a.length=0}function r(d){let f=0;return d.isInstancedMesh&&(f+=2),d.isSkinnedMesh&&(f+=1),f}function o(d,f,x,v,m,g){let y=i[t];return y===void 0?(y={id:d.id,object:d,geometry:f,material:x,materialVariant:r(d),groupOrder:v,renderOrder:d.renderOrder,z:m,group:g},i[t]=y):(y.id=d.id,y.object=d,y.geometry=f,y.material=x,y.materialVariant=r(d),y.groupOrder=v,y.renderOrder=d.renderOrder,y.z=m,y.group=g),t++,y}function c(d,f,x,v,m,g,y){y.reversedDepth===!0&&(m=-m);let w=o(d,f,x,v,m,g);x.transmission>0?n.push(w):x.transparent===!0?a.push(w):e.push(w)}function l(d,f,x,v,m,g){let y=o(d,f,x,v,m,g);x.transmission>0?n.unshift(y):x.transparent===!0?a.unshift(y):e.unshift(y)}function h(d,f){e.length>1&&e.sort(d||H_),n.length>1&&n.sort(f||sp),a.length>1&&a.sort(f||sp)}function u(){for(let d=t,f=i.length;d<f;d++){let x=i[d];if(x.id===null)break;x.id=null,x.object=null,x.geometry=null,x.material=null,x.group=null}}return{opaque:e,transmissive:n,transparent:a,init:s,push:c,unshift:l,finish:u,sort:h}}function G_(){let i=new WeakMap;function t(n,a){let s=i.get(n),r;return s===void 0?(r=new rp,i.set(n,[r])):a>=s.length?(r=new rp,s.push(r)):r=s[a],r}function e(){i=new WeakMap}return{get:t,dispose:e}}function W_(){let i={};return{get:function(t){if(i[t.id]!==void 0)return i[t.id];let e;switch(t.type){case"SunLight":case"DirectionalLight":e={direction:new z,color:new jt};break;case"SpotLight":e={position:new z,direction:new z,color:new jt,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":e={position:new z,color:new jt,distance:0,decay:0};break;case"HemisphereLight":e={direction:new z,skyColor:new jt,groundColor:new jt};break;case"RectAreaLight":e={color:new jt,position:new z,halfWidth:new z,halfHeight:new z};break}return i[t.id]=e,e}}}function j_(){let i={};return{get:function(t){if(i[t.id]!==void 0)return i[t.id];let e;switch(t.type){case"SunLight":case"DirectionalLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Bt};break;case"SpotLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Bt};break;case"PointLight":e={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new Bt,shadowCameraNear:1,shadowCameraFar:1e3};break}return i[t.id]=e,e}}}function q_(i,t){return(t.castShadow?2:0)-(i.castShadow?2:0)+(t.map?1:0)-(i.map?1:0)}function Y_(i){let t=new W_,e=j_(),n={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let l=0;l<9;l++)n.probe.push(new z);let a=new z,s=new oe,r=new oe;function o(l){let h=0,u=0,d=0;for(let N=0;N<9;N++)n.probe[N].set(0,0,0);let f=0,x=0,v=0,m=0,g=0,y=0,w=0,p=0,_=0,S=0,b=0,M=0,E=0,A=0;l.sort(q_);for(let N=0,L=l.length;N<L;N++){let P=l[N],U=P.color,V=P.intensity,O=P.distance,Q=null;if(P.shadow&&P.shadow.map&&(P.shadow.map.texture.format===hi?Q=P.shadow.map.texture:Q=P.shadow.map.depthTexture||P.shadow.map.texture),P.isAmbientLight)h+=U.r*V,u+=U.g*V,d+=U.b*V;else if(P.isLightProbe){for(let G=0;G<9;G++)n.probe[G].addScaledVector(P.sh.coefficients[G],V);A++}else if(P.isSunLight){let G=t.get(P);if(G.color.copy(P.color).multiplyScalar(P.intensity),P.castShadow){let Z=P.shadow,et=e.get(P);et.shadowIntensity=Z.intensity,et.shadowBias=Z.bias,et.shadowNormalBias=Z.normalBias,et.shadowRadius=Z.radius,et.shadowMapSize.copy(Z.mapSize).multiply(Z.getFrameExtents()),n.sunShadow[x]=et,n.sunShadowMap[x]=Q;let ht=Z.getViewportCount();for(let Pt=0;Pt<ht;Pt++)n.sunShadowMatrix[v+Pt]=Z.getMatrix(Pt),n.sunShadowCascade[v+Pt]=Z._cascadeData[Pt];v+=ht,x++}n.sun[f]=G,f++}else if(P.isDirectionalLight){let G=t.get(P);if(G.color.copy(P.color).multiplyScalar(P.intensity),P.castShadow){let Z=P.shadow,et=e.get(P);et.shadowIntensity=Z.intensity,et.shadowBias=Z.bias,et.shadowNormalBias=Z.normalBias,et.shadowRadius=Z.radius,et.shadowMapSize=Z.mapSize,n.directionalShadow[m]=et,n.directionalShadowMap[m]=Q,n.directionalShadowMatrix[m]=P.shadow.matrix,_++}n.directional[m]=G,m++}else if(P.isSpotLight){let G=t.get(P);G.position.setFromMatrixPosition(P.matrixWorld),G.color.copy(U).multiplyScalar(V),G.distance=O,G.coneCos=Math.cos(P.angle),G.penumbraCos=Math.cos(P.angle*(1-P.penumbra)),G.decay=P.decay,n.spot[y]=G;let Z=P.shadow;if(P.map&&(n.spotLightMap[M]=P.map,M++,Z.updateMatrices(P),P.castShadow&&E++),n.spotLightMatrix[y]=Z.matrix,P.castShadow){let et=e.get(P);et.shadowIntensity=Z.intensity,et.shadowBias=Z.bias,et.shadowNormalBias=Z.normalBias,et.shadowRadius=Z.radius,et.shadowMapSize=Z.mapSize,n.spotShadow[y]=et,n.spotShadowMap[y]=Q,b++}y++}else if(P.isRectAreaLight){let G=t.get(P);G.color.copy(U).multiplyScalar(V),G.halfWidth.set(P.width*.5,0,0),G.halfHeight.set(0,P.height*.5,0),n.rectArea[w]=G,w++}else if(P.isPointLight){let G=t.get(P);if(G.color.copy(P.color).multiplyScalar(P.intensity),G.distance=P.distance,G.decay=P.decay,P.castShadow){let Z=P.shadow,et=e.get(P);et.shadowIntensity=Z.intensity,et.shadowBias=Z.bias,et.shadowNormalBias=Z.normalBias,et.shadowRadius=Z.radius,et.shadowMapSize=Z.mapSize,et.shadowCameraNear=Z.camera.near,et.shadowCameraFar=Z.camera.far,n.pointShadow[g]=et,n.pointShadowMap[g]=Q,n.pointShadowMatrix[g]=P.shadow.matrix,S++}n.point[g]=G,g++}else if(P.isHemisphereLight){let G=t.get(P);G.skyColor.copy(P.color).multiplyScalar(V),G.groundColor.copy(P.groundColor).multiplyScalar(V),n.hemi[p]=G,p++}}w>0&&(i.has("OES_texture_float_linear")===!0?(n.rectAreaLTC1=yt.LTC_FLOAT_1,n.rectAreaLTC2=yt.LTC_FLOAT_2):(n.rectAreaLTC1=yt.LTC_HALF_1,n.rectAreaLTC2=yt.LTC_HALF_2)),n.ambient[0]=h,n.ambient[1]=u,n.ambient[2]=d;let I=n.hash;(I.sunLength!==f||I.directionalLength!==m||I.pointLength!==g||I.spotLength!==y||I.rectAreaLength!==w||I.hemiLength!==p||I.numSunShadows!==x||I.numDirectionalShadows!==_||I.numPointShadows!==S||I.numSpotShadows!==b||I.numSpotMaps!==M||I.numLightProbes!==A)&&(n.sun.length=f,n.directional.length=m,n.spot.length=y,n.rectArea.length=w,n.point.length=g,n.hemi.length=p,n.sunShadow.length=x,n.sunShadowMap.length=x,n.sunShadowMatrix.length=v,n.sunShadowCascade.length=v,n.directionalShadow.length=_,n.directionalShadowMap.length=_,n.directionalShadowMatrix.length=_,n.pointShadow.length=S,n.pointShadowMap.length=S,n.pointShadowMatrix.length=S,n.spotShadow.length=b,n.spotShadowMap.length=b,n.spotLightMatrix.length=b+M-E,n.spotLightMap.length=M,n.numSpotLightShadowsWithMaps=E,n.numLightProbes=A,I.sunLength=f,I.directionalLength=m,I.pointLength=g,I.spotLength=y,I.rectAreaLength=w,I.hemiLength=p,I.numSunShadows=x,I.numDirectionalShadows=_,I.numPointShadows=S,I.numSpotShadows=b,I.numSpotMaps=M,I.numLightProbes=A,n.version=X_++)}function c(l,h){let u=0,d=0,f=0,x=0,v=0,m=0,g=h.matrixWorldInverse;for(let y=0,w=l.length;y<w;y++){let p=l[y];if(p.isSunLight){let _=n.sun[u];_.direction.setFromMatrixPosition(p.matrixWorld),_.direction.transformDirection(g),u++}else if(p.isDirectionalLight){let _=n.directional[d];_.direction.setFromMatrixPosition(p.matrixWorld),a.setFromMatrixPosition(p.target.matrixWorld),_.direction.sub(a),_.direction.transformDirection(g),d++}else if(p.isSpotLight){let _=n.spot[x];_.position.setFromMatrixPosition(p.matrixWorld),_.position.applyMatrix4(g),_.direction.setFromMatrixPosition(p.matrixWorld),a.setFromMatrixPosition(p.target.matrixWorld),_.direction.sub(a),_.direction.transformDirection(g),x++}else if(p.isRectAreaLight){let _=n.rectArea[v];_.position.setFromMatrixPosition(p.matrixWorld),_.position.applyMatrix4(g),r.identity(),s.copy(p.matrixWorld),s.premultiply(g),r.extractRotation(s),_.halfWidth.set(p.width*.5,0,0),_.halfHeight.set(0,p.height*.5,0),_.halfWidth.applyMatrix4(r),_.halfHeight.applyMatrix4(r),v++}else if(p.isPointLight){let _=n.point[f];_.position.setFromMatrixPosition(p.matrixWorld),_.position.applyMatrix4(g),f++}else if(p.isHemisphereLight){let _=n.hemi[m];_.direction.setFromMatrixPosition(p.matrixWorld),_.direction.transformDirection(g),m++}}}return{setup:o,setupView:c,state:n}}function op(i){let t=new Y_(i),e=[],n=[],a=[];function s(u){h.camera=u,e.length=0,n.length=0,a.length=0}function r(u){u.isLightProbeGrid?a.push(u):e.push(u)}function o(u){n.push(u)}function c(){t.setup(e),a.sort((u,d)=>u.priority-d.priority||u.id-d.id)}function l(u){t.setupView(e,u)}let h={lightsArray:e,shadowsArray:n,lightProbeGridArray:a,camera:null,lights:t,transmissionRenderTarget:{},textureUnits:0};return{init:s,state:h,setupLights:c,setupLightsView:l,pushLight:r,pushShadow:o}}function J_(i){let t=new WeakMap;function e(a,s=0){let r=t.get(a),o;return r===void 0?(o=new op(i),t.set(a,[o])):s>=r.length?(o=new op(i),r.push(o)):o=r[s],o}function n(){t=new WeakMap}return{get:e,dispose:n}}function tv(i,t,e){let n=new Ri,a=new Bt,s=new Bt,r=new ce,o=new tc,c=new ec,l={},h=e.maxTextureSize,u={[ci]:je,[je]:ci,[kn]:kn},d=new Bn({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new Bt},radius:{value:4}},vertexShader:K_,fragmentShader:Z_}),f=d.clone();f.defines.HORIZONTAL_PASS=1;let x=new Ue;x.setAttribute("position",new pn(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));let v=new nn(x,d),m=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=Tr;let g=this.type;this.render=function(S,b,M){if(m.enabled===!1||m.autoUpdate===!1&&m.needsUpdate===!1||S.length===0)return;this.type===sf&&(Ft("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=Tr);let E=i.getRenderTarget(),A=i.getActiveCubeFace(),I=i.getActiveMipmapLevel(),N=i.state;N.setBlending(ya),N.buffers.depth.getReversed()===!0?N.buffers.color.setClear(0,0,0,0):N.buffers.color.setClear(1,1,1,1),N.buffers.depth.setTest(!0),N.setScissorTest(!1);let L=g!==this.type;L&&b.traverse(function(P){P.material&&(Array.isArray(P.material)?P.material.forEach(U=>U.needsUpdate=!0):P.material.needsUpdate=!0)});for(let P=0,U=S.length;P<U;P++){let V=S[P],O=V.shadow;if(O===void 0){Ft("WebGLShadowMap:",V,"has no shadow.");continue}if(O.autoUpdate===!1&&O.needsUpdate===!1)continue;a.copy(O.mapSize);let Q=O.getFrameExtents();a.multiply(Q),s.copy(O.mapSize),(a.x>h||a.y>h)&&(a.x>h&&(s.x=Math.floor(h/Q.x),a.x=s.x*Q.x,O.mapSize.x=s.x),a.y>h&&(s.y=Math.floor(h/Q.y),a.y=s.y*Q.y,O.mapSize.y=s.y));let G=i.state.buffers.depth.getReversed();if(O.camera._reversedDepth=G,O.map===null||L===!0){if(O.map!==null&&(O.map.depthTexture!==null&&(O.map.depthTexture.dispose(),O.map.depthTexture=null),O.map.dispose()),this.type===cs){if(V.isPointLight){Ft("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}O.map=new Nn(a.x,a.y,{format:hi,type:Zn,minFilter:mn,magFilter:mn,generateMipmaps:!1}),O.map.texture.name=V.name+".shadowMap",O.map.depthTexture=new Ci(a.x,a.y,gn),O.map.depthTexture.name=V.name+".shadowMapDepth",O.map.depthTexture.format=Ti,O.map.depthTexture.compareFunction=null,O.map.depthTexture.minFilter=De,O.map.depthTexture.magFilter=De}else V.isPointLight?(O.map=new Vr(a.x),O.map.depthTexture=new lr(a.x,An)):(O.map=new Nn(a.x,a.y),O.map.depthTexture=new Ci(a.x,a.y,An)),O.map.depthTexture.name=V.name+".shadowMap",O.map.depthTexture.format=Ti,this.type===Tr?(O.map.depthTexture.compareFunction=G?Yh:qh,O.map.depthTexture.minFilter=mn,O.map.depthTexture.magFilter=mn):(O.map.depthTexture.compareFunction=null,O.map.depthTexture.minFilter=De,O.map.depthTexture.magFilter=De);O.camera.updateProjectionMatrix()}O.map.isWebGLCubeRenderTarget!==!0&&(O.map.width!==a.x||O.map.height!==a.y)&&O.map.setSize(a.x,a.y);let Z=O.map.isWebGLCubeRenderTarget?6:O.getViewportCount();V.isPointLight!==!0&&O.updateMatrices(V,M);let et=(O.camera.layers.mask&4294967294)!==0?O.camera.layers:M.layers;for(let ht=0;ht<Z;ht++){let Pt=O.getCamera(ht);if(V.isPointLight){let Y=O.camera,ct=O.matrix,mt=V.distance||Y.far;mt!==Y.far&&(Y.far=mt,Y.updateProjectionMatrix()),kr.setFromMatrixPosition(V.matrixWorld),Y.position.copy(kr),fd.copy(Y.position),fd.add(Q_[ht]),Y.up.copy($_[ht]),Y.lookAt(fd),Y.updateMatrixWorld(),ct.makeTranslation(-kr.x,-kr.y,-kr.z),cp.multiplyMatrices(Y.projectionMatrix,Y.matrixWorldInverse),O._frustum.setFromProjectionMatrix(cp,Y.coordinateSystem,Y.reversedDepth)}if(O.map.isWebGLCubeRenderTarget)i.setRenderTarget(O.map,ht),i.clear();else{ht===0&&(i.setRenderTarget(O.map),i.clear());let Y=O.getViewport(ht);r.set(s.x*Y.x,s.y*Y.y,s.x*Y.z,s.y*Y.w),N.viewport(r)}n=O.getFrustum(ht),p(b,M,Pt,V,et,this.type)}O.isPointLightShadow!==!0&&this.type===cs&&y(O,M),O.needsUpdate=!1}g=this.type,m.needsUpdate=!1,i.setRenderTarget(E,A,I)};function y(S,b){let M=t.update(v);d.defines.VSM_SAMPLES!==S.blurSamples&&(d.defines.VSM_SAMPLES=S.blurSamples,f.defines.VSM_SAMPLES=S.blurSamples,d.needsUpdate=!0,f.needsUpdate=!0),S.mapPass===null?S.mapPass=new Nn(a.x,a.y,{format:hi,type:Zn}):(S.mapPass.width!==S.map.width||S.mapPass.height!==S.map.height)&&S.mapPass.setSize(S.map.width,S.map.height),d.uniforms.shadow_pass.value=S.map.depthTexture,d.uniforms.resolution.value.set(S.map.width,S.map.height),d.uniforms.radius.value=S.radius,i.setRenderTarget(S.mapPass),i.clear(),i.renderBufferDirect(b,null,M,d,v,null),f.uniforms.shadow_pass.value=S.mapPass.texture,f.uniforms.resolution.value.set(S.map.width,S.map.height),f.uniforms.radius.value=S.radius,i.setRenderTarget(S.map),i.clear(),i.renderBufferDirect(b,null,M,f,v,null)}function w(S,b,M,E){let A=null,I=M.isPointLight===!0?S.customDistanceMaterial:S.customDepthMaterial;if(I!==void 0)A=I;else if(A=M.isPointLight===!0?c:o,i.localClippingEnabled&&b.clipShadows===!0&&Array.isArray(b.clippingPlanes)&&b.clippingPlanes.length!==0||b.displacementMap&&b.displacementScale!==0||b.alphaMap&&b.alphaTest>0||b.map&&b.alphaTest>0||b.alphaToCoverage===!0){let N=A.uuid,L=b.uuid,P=l[N];P===void 0&&(P={},l[N]=P);let U=P[L];U===void 0&&(U=A.clone(),P[L]=U,b.addEventListener("dispose",_)),A=U}if(A.visible=b.visible,A.wireframe=b.wireframe,E===cs?A.side=b.shadowSide!==null?b.shadowSide:b.side:A.side=b.shadowSide!==null?b.shadowSide:u[b.side],A.alphaMap=b.alphaMap,A.alphaTest=b.alphaToCoverage===!0?.5:b.alphaTest,A.map=b.map,A.clipShadows=b.clipShadows,A.clippingPlanes=b.clippingPlanes,A.clipIntersection=b.clipIntersection,A.displacementMap=b.displacementMap,A.displacementScale=b.displacementScale,A.displacementBias=b.displacementBias,A.wireframeLinewidth=b.wireframeLinewidth,A.linewidth=b.linewidth,M.isPointLight===!0&&A.isMeshDistanceMaterial===!0){let N=i.properties.get(A);N.light=M}return A}function p(S,b,M,E,A,I){if(S.visible===!1)return;if(S.layers.test(A)&&(S.isMesh||S.isLine||S.isPoints)&&(S.castShadow||S.receiveShadow&&I===cs)&&(!S.frustumCulled||S.intersectsFrustum(n))){S.modelViewMatrix.multiplyMatrices(M.matrixWorldInverse,S.matrixWorld);let P=t.update(S),U=S.material;if(Array.isArray(U)){let V=P.groups;for(let O=0,Q=V.length;O<Q;O++){let G=V[O],Z=U[G.materialIndex];if(Z&&Z.visible){let et=w(S,Z,E,I);S.onBeforeShadow(i,S,b,M,P,et,G),i.renderBufferDirect(M,null,P,et,S,G),S.onAfterShadow(i,S,b,M,P,et,G)}}}else if(U.visible){let V=w(S,U,E,I);S.onBeforeShadow(i,S,b,M,P,V,null),i.renderBufferDirect(M,null,P,V,S,null),S.onAfterShadow(i,S,b,M,P,V,null)}}let L=S.children;for(let P=0,U=L.length;P<U;P++)p(L[P],b,M,E,A,I)}function _(S){S.target.removeEventListener("dispose",_);for(let M in l){let E=l[M],A=S.target.uuid;A in E&&(E[A].dispose(),delete E[A])}}}function ev(i,t){function e(){let R=!1,k=new ce,H=null,j=new ce(0,0,0,0);return{setMask:function(it){H!==it&&!R&&(i.colorMask(it,it,it,it),H=it)},setLocked:function(it){R=it},setClear:function(it,st,_t,Ct,ot){ot===!0&&(it*=Ct,st*=Ct,_t*=Ct),k.set(it,st,_t,Ct),j.equals(k)===!1&&(i.clearColor(it,st,_t,Ct),j.copy(k))},reset:function(){R=!1,H=null,j.set(-1,0,0,0)}}}function n(){let R=!1,k=!1,H=null,j=null,it=null;return{setReversed:function(st){if(k!==st){let _t=t.get("EXT_clip_control");st?_t.clipControlEXT(_t.LOWER_LEFT_EXT,_t.ZERO_TO_ONE_EXT):_t.clipControlEXT(_t.LOWER_LEFT_EXT,_t.NEGATIVE_ONE_TO_ONE_EXT),k=st;let Ct=it;it=null,this.setClear(Ct)}},getReversed:function(){return k},setTest:function(st){st?gt(i.DEPTH_TEST):Ot(i.DEPTH_TEST)},setMask:function(st){H!==st&&!R&&(i.depthMask(st),H=st)},setFunc:function(st){if(k&&(st=Bf[st]),j!==st){switch(st){case Oo:i.depthFunc(i.NEVER);break;case Fo:i.depthFunc(i.ALWAYS);break;case Bo:i.depthFunc(i.LESS);break;case Ja:i.depthFunc(i.LEQUAL);break;case ko:i.depthFunc(i.EQUAL);break;case zo:i.depthFunc(i.GEQUAL);break;case Vo:i.depthFunc(i.GREATER);break;case Ho:i.depthFunc(i.NOTEQUAL);break;default:i.depthFunc(i.LEQUAL)}j=st}},setLocked:function(st){R=st},setClear:function(st){it!==st&&(it=st,k&&(st=1-st),i.clearDepth(st))},reset:function(){R=!1,H=null,j=null,it=null,k=!1}}}function a(){let R=!1,k=null,H=null,j=null,it=null,st=null,_t=null,Ct=null,ot=null;return{setTest:function(vt){R||(vt?gt(i.STENCIL_TEST):Ot(i.STENCIL_TEST))},setMask:function(vt){k!==vt&&!R&&(i.stencilMask(vt),k=vt)},setFunc:function(vt,Ut,pt){(H!==vt||j!==Ut||it!==pt)&&(i.stencilFunc(vt,Ut,pt),H=vt,j=Ut,it=pt)},setOp:function(vt,Ut,pt){(st!==vt||_t!==Ut||Ct!==pt)&&(i.stencilOp(vt,Ut,pt),st=vt,_t=Ut,Ct=pt)},setLocked:function(vt){R=vt},setClear:function(vt){ot!==vt&&(i.clearStencil(vt),ot=vt)},reset:function(){R=!1,k=null,H=null,j=null,it=null,st=null,_t=null,Ct=null,ot=null}}}let s=new e,r=new n,o=new a,c={},l=new WeakMap,h={},u={},d={},f=new WeakMap,x=[],v=null,m=!1,g=null,y=null,w=null,p=null,_=null,S=null,b=null,M=new jt(0,0,0),E=0,A=!1,I=null,N=null,L=null,P=null,U=null,V=i.getParameter(i.MAX_COMBINED_TEXTURE_IMAGE_UNITS),O=!1,Q=0,G=i.getParameter(i.VERSION);G.indexOf("WebGL")!==-1?(Q=parseFloat(/^WebGL (\d)/.exec(G)[1]),O=Q>=1):G.indexOf("OpenGL ES")!==-1&&(Q=parseFloat(/^OpenGL ES (\d)/.exec(G)[1]),O=Q>=2);let Z=null,et={},ht=i.getParameter(i.SCISSOR_BOX),Pt=i.getParameter(i.VIEWPORT),Y=new ce().fromArray(ht),ct=new ce().fromArray(Pt);function mt(R,k,H,j){let it=new Uint8Array(4),st=i.createTexture();i.bindTexture(R,st),i.texParameteri(R,i.TEXTURE_MIN_FILTER,i.NEAREST),i.texParameteri(R,i.TEXTURE_MAG_FILTER,i.NEAREST);for(let _t=0;_t<H;_t++)R===i.TEXTURE_3D||R===i.TEXTURE_2D_ARRAY?i.texImage3D(k,0,i.RGBA,1,1,j,0,i.RGBA,i.UNSIGNED_BYTE,it):i.texImage2D(k+_t,0,i.RGBA,1,1,0,i.RGBA,i.UNSIGNED_BYTE,it);return st}let Tt={};Tt[i.TEXTURE_2D]=mt(i.TEXTURE_2D,i.TEXTURE_2D,1),Tt[i.TEXTURE_CUBE_MAP]=mt(i.TEXTURE_CUBE_MAP,i.TEXTURE_CUBE_MAP_POSITIVE_X,6),Tt[i.TEXTURE_2D_ARRAY]=mt(i.TEXTURE_2D_ARRAY,i.TEXTURE_2D_ARRAY,1,1),Tt[i.TEXTURE_3D]=mt(i.TEXTURE_3D,i.TEXTURE_3D,1,1),s.setClear(0,0,0,1),r.setClear(1),o.setClear(0),gt(i.DEPTH_TEST),r.setFunc(Ja),St(!1),wt(Rh),gt(i.CULL_FACE),Ae(ya);function gt(R){h[R]!==!0&&(i.enable(R),h[R]=!0)}function Ot(R){h[R]!==!1&&(i.disable(R),h[R]=!1)}function ge(R,k){return d[R]!==k?(i.bindFramebuffer(R,k),d[R]=k,R===i.DRAW_FRAMEBUFFER&&(d[i.FRAMEBUFFER]=k),R===i.FRAMEBUFFER&&(d[i.DRAW_FRAMEBUFFER]=k),!0):!1}function Dt(R,k){let H=x,j=!1;if(R){H=f.get(k),H===void 0&&(H=[],f.set(k,H));let it=R.textures;if(H.length!==it.length||H[0]!==i.COLOR_ATTACHMENT0){for(let st=0,_t=it.length;st<_t;st++)H[st]=i.COLOR_ATTACHMENT0+st;H.length=it.length,j=!0}}else H[0]!==i.BACK&&(H[0]=i.BACK,j=!0);j&&i.drawBuffers(H)}function kt(R){return v!==R?(i.useProgram(R),v=R,!0):!1}let Yt={[_a]:i.FUNC_ADD,[of]:i.FUNC_SUBTRACT,[cf]:i.FUNC_REVERSE_SUBTRACT};Yt[lf]=i.MIN,Yt[hf]=i.MAX;let Xt={[df]:i.ZERO,[uf]:i.ONE,[ff]:i.SRC_COLOR,[Lh]:i.SRC_ALPHA,[yf]:i.SRC_ALPHA_SATURATE,[bf]:i.DST_COLOR,[mf]:i.DST_ALPHA,[pf]:i.ONE_MINUS_SRC_COLOR,[Dh]:i.ONE_MINUS_SRC_ALPHA,[xf]:i.ONE_MINUS_DST_COLOR,[gf]:i.ONE_MINUS_DST_ALPHA,[_f]:i.CONSTANT_COLOR,[vf]:i.ONE_MINUS_CONSTANT_COLOR,[Mf]:i.CONSTANT_ALPHA,[Sf]:i.ONE_MINUS_CONSTANT_ALPHA};function Ae(R,k,H,j,it,st,_t,Ct,ot,vt){if(R===ya){m===!0&&(Ot(i.BLEND),m=!1);return}if(m===!1&&(gt(i.BLEND),m=!0),R!==rf){if(R!==g||vt!==A){if((y!==_a||_!==_a)&&(i.blendEquation(i.FUNC_ADD),y=_a,_=_a),vt)switch(R){case ls:i.blendFuncSeparate(i.ONE,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Ch:i.blendFunc(i.ONE,i.ONE);break;case Nh:i.blendFuncSeparate(i.ZERO,i.ONE_MINUS_SRC_COLOR,i.ZERO,i.ONE);break;case Ph:i.blendFuncSeparate(i.DST_COLOR,i.ONE_MINUS_SRC_ALPHA,i.ZERO,i.ONE);break;default:zt("WebGLState: Invalid blending: ",R);break}else switch(R){case ls:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case Ch:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE,i.ONE,i.ONE);break;case Nh:zt("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case Ph:zt("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:zt("WebGLState: Invalid blending: ",R);break}w=null,p=null,S=null,b=null,M.set(0,0,0),E=0,g=R,A=vt}return}it=it||k,st=st||H,_t=_t||j,(k!==y||it!==_)&&(i.blendEquationSeparate(Yt[k],Yt[it]),y=k,_=it),(H!==w||j!==p||st!==S||_t!==b)&&(i.blendFuncSeparate(Xt[H],Xt[j],Xt[st],Xt[_t]),w=H,p=j,S=st,b=_t),(Ct.equals(M)===!1||ot!==E)&&(i.blendColor(Ct.r,Ct.g,Ct.b,ot),M.copy(Ct),E=ot),g=R,A=!1}function nt(R,k){R.side===kn?Ot(i.CULL_FACE):gt(i.CULL_FACE);let H=R.side===je;k&&(H=!H),St(H),R.blending===ls&&R.transparent===!1?Ae(ya):Ae(R.blending,R.blendEquation,R.blendSrc,R.blendDst,R.blendEquationAlpha,R.blendSrcAlpha,R.blendDstAlpha,R.blendColor,R.blendAlpha,R.premultipliedAlpha),r.setFunc(R.depthFunc),r.setTest(R.depthTest),r.setMask(R.depthWrite),s.setMask(R.colorWrite);let j=R.stencilWrite;o.setTest(j),j&&(o.setMask(R.stencilWriteMask),o.setFunc(R.stencilFunc,R.stencilRef,R.stencilFuncMask),o.setOp(R.stencilFail,R.stencilZFail,R.stencilZPass)),Ht(R.polygonOffset,R.polygonOffsetFactor,R.polygonOffsetUnits),R.alphaToCoverage===!0?gt(i.SAMPLE_ALPHA_TO_COVERAGE):Ot(i.SAMPLE_ALPHA_TO_COVERAGE)}function St(R){I!==R&&(R?i.frontFace(i.CW):i.frontFace(i.CCW),I=R)}function wt(R){R!==nf?(gt(i.CULL_FACE),R!==N&&(R===Rh?i.cullFace(i.BACK):R===af?i.cullFace(i.FRONT):i.cullFace(i.FRONT_AND_BACK))):Ot(i.CULL_FACE),N=R}function Qt(R){R!==L&&(O&&i.lineWidth(R),L=R)}function Ht(R,k,H){R?(gt(i.POLYGON_OFFSET_FILL),(P!==k||U!==H)&&(P=k,U=H,r.getReversed()&&(k=-k,H=-H),i.polygonOffset(k,H))):Ot(i.POLYGON_OFFSET_FILL)}function be(R){R?gt(i.SCISSOR_TEST):Ot(i.SCISSOR_TEST)}function fe(R){R===void 0&&(R=i.TEXTURE0+V-1),Z!==R&&(i.activeTexture(R),Z=R)}function ne(R,k,H){H===void 0&&(Z===null?H=i.TEXTURE0+V-1:H=Z);let j=et[H];j===void 0&&(j={type:void 0,texture:void 0},et[H]=j),(j.type!==R||j.texture!==k)&&(Z!==H&&(i.activeTexture(H),Z=H),i.bindTexture(R,k||Tt[R]),j.type=R,j.texture=k)}function B(){let R=et[Z];R!==void 0&&R.type!==void 0&&(i.bindTexture(R.type,null),R.type=void 0,R.texture=void 0)}function Ee(){try{i.compressedTexImage2D(...arguments)}catch(R){zt("WebGLState:",R)}}function $t(){try{i.compressedTexImage3D(...arguments)}catch(R){zt("WebGLState:",R)}}function Jt(){try{i.texSubImage2D(...arguments)}catch(R){zt("WebGLState:",R)}}function dt(){try{i.texSubImage3D(...arguments)}catch(R){zt("WebGLState:",R)}}function se(){try{i.compressedTexSubImage2D(...arguments)}catch(R){zt("WebGLState:",R)}}function At(){try{i.compressedTexSubImage3D(...arguments)}catch(R){zt("WebGLState:",R)}}function Lt(){try{i.texStorage2D(...arguments)}catch(R){zt("WebGLState:",R)}}function D(){try{i.texStorage3D(...arguments)}catch(R){zt("WebGLState:",R)}}function T(){try{i.texImage2D(...arguments)}catch(R){zt("WebGLState:",R)}}function W(){try{i.texImage3D(...arguments)}catch(R){zt("WebGLState:",R)}}function at(R){return u[R]!==void 0?u[R]:i.getParameter(R)}function tt(R,k){u[R]!==k&&(i.pixelStorei(R,k),u[R]=k)}function lt(R){Y.equals(R)===!1&&(i.scissor(R.x,R.y,R.z,R.w),Y.copy(R))}function ut(R){ct.equals(R)===!1&&(i.viewport(R.x,R.y,R.z,R.w),ct.copy(R))}function $(R,k){let H=l.get(k);H===void 0&&(H=new WeakMap,l.set(k,H));let j=H.get(R);j===void 0&&(j=i.getUniformBlockIndex(k,R.name),i.uniformBlockBinding(k,j,j),H.set(R,j))}function J(R,k,H){let it=l.get(k).get(R);c[it]!==H&&(i.bindBufferBase(i.UNIFORM_BUFFER,it,H),c[it]=H)}function ft(){i.disable(i.BLEND),i.disable(i.CULL_FACE),i.disable(i.DEPTH_TEST),i.disable(i.POLYGON_OFFSET_FILL),i.disable(i.SCISSOR_TEST),i.disable(i.STENCIL_TEST),i.disable(i.SAMPLE_ALPHA_TO_COVERAGE),i.blendEquation(i.FUNC_ADD),i.blendFunc(i.ONE,i.ZERO),i.blendFuncSeparate(i.ONE,i.ZERO,i.ONE,i.ZERO),i.blendColor(0,0,0,0),i.colorMask(!0,!0,!0,!0),i.clearColor(0,0,0,0),i.depthMask(!0),i.depthFunc(i.LESS),r.setReversed(!1),i.clearDepth(1),i.stencilMask(4294967295),i.stencilFunc(i.ALWAYS,0,4294967295),i.stencilOp(i.KEEP,i.KEEP,i.KEEP),i.clearStencil(0),i.cullFace(i.BACK),i.frontFace(i.CCW),i.polygonOffset(0,0),i.activeTexture(i.TEXTURE0),i.bindFramebuffer(i.FRAMEBUFFER,null),i.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),i.bindFramebuffer(i.READ_FRAMEBUFFER,null),i.useProgram(null),i.lineWidth(1),i.scissor(0,0,i.canvas.width,i.canvas.height),i.viewport(0,0,i.canvas.width,i.canvas.height),i.pixelStorei(i.PACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,!1),i.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),i.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,i.BROWSER_DEFAULT_WEBGL),i.pixelStorei(i.PACK_ROW_LENGTH,0),i.pixelStorei(i.PACK_SKIP_PIXELS,0),i.pixelStorei(i.PACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_ROW_LENGTH,0),i.pixelStorei(i.UNPACK_IMAGE_HEIGHT,0),i.pixelStorei(i.UNPACK_SKIP_PIXELS,0),i.pixelStorei(i.UNPACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_SKIP_IMAGES,0),h={},u={},Z=null,et={},d={},c={},f=new WeakMap,x=[],v=null,m=!1,g=null,y=null,w=null,p=null,_=null,S=null,b=null,M=new jt(0,0,0),E=0,A=!1,I=null,N=null,L=null,P=null,U=null,Y.set(0,0,i.canvas.width,i.canvas.height),ct.set(0,0,i.canvas.width,i.canvas.height),s.reset(),r.reset(),o.reset()}return{buffers:{color:s,depth:r,stencil:o},enable:gt,disable:Ot,bindFramebuffer:ge,drawBuffers:Dt,useProgram:kt,setBlending:Ae,setMaterial:nt,setFlipSided:St,setCullFace:wt,setLineWidth:Qt,setPolygonOffset:Ht,setScissorTest:be,activeTexture:fe,bindTexture:ne,unbindTexture:B,compressedTexImage2D:Ee,compressedTexImage3D:$t,texImage2D:T,texImage3D:W,pixelStorei:tt,getParameter:at,updateUBOMapping:$,uniformBlockBinding:J,texStorage2D:Lt,texStorage3D:D,texSubImage2D:Jt,texSubImage3D:dt,compressedTexSubImage2D:se,compressedTexSubImage3D:At,scissor:lt,viewport:ut,reset:ft}}function nv(i,t,e,n,a,s,r){let o=t.has("WEBGL_multisampled_render_to_texture")?t.get("WEBGL_multisampled_render_to_texture"):null,c=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),l=new Bt,h=new WeakMap,u=new Set,d,f=new WeakMap,x=new Set,v=new FinalizationRegistry(D=>x.delete(D)),m=!1;try{m=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function g(D,T){return m?new OffscreenCanvas(D,T):Qs("canvas")}function y(D,T,W){let at=1,tt=Lt(D);if((tt.width>W||tt.height>W)&&(at=W/Math.max(tt.width,tt.height)),at<1)if(typeof HTMLImageElement<"u"&&D instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&D instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&D instanceof ImageBitmap||typeof VideoFrame<"u"&&D instanceof VideoFrame){let lt=Math.floor(at*tt.width),ut=Math.floor(at*tt.height);d===void 0&&(d=g(lt,ut));let $=T?g(lt,ut):d;return $.width=lt,$.height=ut,$.getContext("2d").drawImage(D,0,0,lt,ut),Ft("WebGLRenderer: Texture has been resized from ("+tt.width+"x"+tt.height+") to ("+lt+"x"+ut+")."),$}else return"data"in D&&Ft("WebGLRenderer: Image in DataTexture is too big ("+tt.width+"x"+tt.height+")."),D;return D}function w(D){return D.generateMipmaps}function p(D){i.generateMipmap(D)}function _(D){return D.isWebGLCubeRenderTarget?i.TEXTURE_CUBE_MAP:D.isWebGL3DRenderTarget?i.TEXTURE_3D:D.isWebGLArrayRenderTarget||D.isCompressedArrayTexture?i.TEXTURE_2D_ARRAY:i.TEXTURE_2D}function S(D,T,W,at,tt,lt=!1){if(D!==null){if(i[D]!==void 0)return i[D];Ft("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+D+"'")}let ut;at&&(ut=t.get("EXT_texture_norm16"),ut||Ft("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let $=T;if(T===i.RED&&(W===i.FLOAT&&($=i.R32F),W===i.HALF_FLOAT&&($=i.R16F),W===i.UNSIGNED_BYTE&&($=i.R8),W===i.UNSIGNED_SHORT&&ut&&($=ut.R16_EXT),W===i.SHORT&&ut&&($=ut.R16_SNORM_EXT)),T===i.RED_INTEGER&&(W===i.UNSIGNED_BYTE&&($=i.R8UI),W===i.UNSIGNED_SHORT&&($=i.R16UI),W===i.UNSIGNED_INT&&($=i.R32UI),W===i.BYTE&&($=i.R8I),W===i.SHORT&&($=i.R16I),W===i.INT&&($=i.R32I)),T===i.RG&&(W===i.FLOAT&&($=i.RG32F),W===i.HALF_FLOAT&&($=i.RG16F),W===i.UNSIGNED_BYTE&&($=i.RG8),W===i.UNSIGNED_SHORT&&ut&&($=ut.RG16_EXT),W===i.SHORT&&ut&&($=ut.RG16_SNORM_EXT)),T===i.RG_INTEGER&&(W===i.UNSIGNED_BYTE&&($=i.RG8UI),W===i.UNSIGNED_SHORT&&($=i.RG16UI),W===i.UNSIGNED_INT&&($=i.RG32UI),W===i.BYTE&&($=i.RG8I),W===i.SHORT&&($=i.RG16I),W===i.INT&&($=i.RG32I)),T===i.RGB_INTEGER&&(W===i.UNSIGNED_BYTE&&($=i.RGB8UI),W===i.UNSIGNED_SHORT&&($=i.RGB16UI),W===i.UNSIGNED_INT&&($=i.RGB32UI),W===i.BYTE&&($=i.RGB8I),W===i.SHORT&&($=i.RGB16I),W===i.INT&&($=i.RGB32I)),T===i.RGBA_INTEGER&&(W===i.UNSIGNED_BYTE&&($=i.RGBA8UI),W===i.UNSIGNED_SHORT&&($=i.RGBA16UI),W===i.UNSIGNED_INT&&($=i.RGBA32UI),W===i.BYTE&&($=i.RGBA8I),W===i.SHORT&&($=i.RGBA16I),W===i.INT&&($=i.RGBA32I)),T===i.RGB&&(W===i.UNSIGNED_SHORT&&ut&&($=ut.RGB16_EXT),W===i.SHORT&&ut&&($=ut.RGB16_SNORM_EXT),W===i.UNSIGNED_INT_5_9_9_9_REV&&($=i.RGB9_E5),W===i.UNSIGNED_INT_10F_11F_11F_REV&&($=i.R11F_G11F_B10F)),T===i.RGBA){let J=lt?Zs:Kt.getTransfer(tt);W===i.FLOAT&&($=i.RGBA32F),W===i.HALF_FLOAT&&($=i.RGBA16F),W===i.UNSIGNED_BYTE&&($=J===pe?i.SRGB8_ALPHA8:i.RGBA8),W===i.UNSIGNED_SHORT&&ut&&($=ut.RGBA16_EXT),W===i.SHORT&&ut&&($=ut.RGBA16_SNORM_EXT),W===i.UNSIGNED_SHORT_4_4_4_4&&($=i.RGBA4),W===i.UNSIGNED_SHORT_5_5_5_1&&($=i.RGB5_A1)}return($===i.R16F||$===i.R32F||$===i.RG16F||$===i.RG32F||$===i.RGBA16F||$===i.RGBA32F)&&t.get("EXT_color_buffer_float"),$}function b(D,T){let W;return D?T===null||T===An||T===Ma?W=i.DEPTH24_STENCIL8:T===gn?W=i.DEPTH32F_STENCIL8:T===Yi&&(W=i.DEPTH24_STENCIL8,Ft("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):T===null||T===An||T===Ma?W=i.DEPTH_COMPONENT24:T===gn?W=i.DEPTH_COMPONENT32F:T===Yi&&(W=i.DEPTH_COMPONENT16),W}function M(D,T){return w(D)===!0||D.isFramebufferTexture&&D.minFilter!==De&&D.minFilter!==mn?Math.log2(Math.max(T.width,T.height))+1:D.mipmaps.length>0?D.mipmaps.length:D.isCompressedTexture&&Array.isArray(D.image)?T.mipmaps.length:1}function E(D){let T=new WeakRef(D);n.get(D).__ref=T,x.add(T),v.register(D,T,T)}function A(D){let T=n.get(D).__ref;T!==void 0&&(x.delete(T),v.unregister(T))}function I(D){L(D.target)}function N(D){P(D.target)}function L(D){D.removeEventListener("dispose",I),A(D),V(D),D.isVideoTexture&&h.delete(D),D.isHTMLTexture&&u.delete(D)}function P(D){D.removeEventListener("dispose",N),A(D),Q(D)}function U(){for(let D of x){let T=D.deref();T!==void 0&&(T.isRenderTarget===!0?P(T):L(T))}x.clear(),u.clear()}function V(D){let T=n.get(D);if(T.__webglInit===void 0)return;let W=D.source,at=f.get(W);if(at){let tt=at[T.__cacheKey];tt.usedTimes--,tt.usedTimes===0&&O(D),Object.keys(at).length===0&&f.delete(W)}n.remove(D)}function O(D){let T=n.get(D);i.deleteTexture(T.__webglTexture);let W=D.source,at=f.get(W);delete at[T.__cacheKey],r.memory.textures--}function Q(D){let T=n.get(D);T.__depthDisposeCallback&&T.__depthDisposeCallback();let W=D.depthTexture;if(W&&W.renderTarget===D&&L(W),D.isWebGLCubeRenderTarget)for(let tt=0;tt<6;tt++){if(Array.isArray(T.__webglFramebuffer[tt]))for(let lt=0;lt<T.__webglFramebuffer[tt].length;lt++)i.deleteFramebuffer(T.__webglFramebuffer[tt][lt]);else i.deleteFramebuffer(T.__webglFramebuffer[tt]);T.__webglDepthbuffer&&i.deleteRenderbuffer(T.__webglDepthbuffer[tt])}else{if(Array.isArray(T.__webglFramebuffer))for(let tt=0;tt<T.__webglFramebuffer.length;tt++)i.deleteFramebuffer(T.__webglFramebuffer[tt]);else i.deleteFramebuffer(T.__webglFramebuffer);if(T.__webglDepthbuffer&&i.deleteRenderbuffer(T.__webglDepthbuffer),T.__webglMultisampledFramebuffer&&i.deleteFramebuffer(T.__webglMultisampledFramebuffer),T.__webglColorRenderbuffer)for(let tt=0;tt<T.__webglColorRenderbuffer.length;tt++)T.__webglColorRenderbuffer[tt]&&i.deleteRenderbuffer(T.__webglColorRenderbuffer[tt]);T.__webglDepthRenderbuffer&&i.deleteRenderbuffer(T.__webglDepthRenderbuffer)}let at=D.textures;for(let tt=0,lt=at.length;tt<lt;tt++){let ut=n.get(at[tt]);ut.__webglTexture&&(i.deleteTexture(ut.__webglTexture),r.memory.textures--),n.remove(at[tt])}n.remove(D)}let G=0;function Z(){G=0}function et(){return G}function ht(D){G=D}function Pt(){let D=G;return D>=a.maxTextures&&Ft("WebGLTextures: Trying to use "+(D+1)+" texture units while this GPU supports only "+a.maxTextures),G+=1,D}function Y(D){let T=[];return T.push(D.wrapS),T.push(D.wrapT),T.push(D.wrapR||0),T.push(D.magFilter),T.push(D.minFilter),T.push(D.anisotropy),T.push(D.internalFormat),T.push(D.format),T.push(D.type),T.push(D.generateMipmaps),T.push(D.mipmapsAutoUpdate),T.push(D.premultiplyAlpha),T.push(D.flipY),T.push(D.unpackAlignment),T.push(D.colorSpace),T.join()}function ct(D,T){let W=n.get(D);if(D.isVideoTexture&&se(D),D.isRenderTargetTexture===!1&&D.isExternalTexture!==!0&&D.version>0&&W.__version!==D.version){let at=D.image;if(at===null)Ft("WebGLRenderer: Texture marked for update but no image data found.");else if(at.complete===!1)Ft("WebGLRenderer: Texture marked for update but image is incomplete");else{nt(W,D,T);return}}else D.isExternalTexture&&(W.__webglTexture=D.sourceTexture?D.sourceTexture:null);e.bindTexture(i.TEXTURE_2D,W.__webglTexture,i.TEXTURE0+T)}function mt(D,T){let W=n.get(D);if(D.isRenderTargetTexture===!1&&D.version>0&&W.__version!==D.version){nt(W,D,T);return}else D.isExternalTexture&&(W.__webglTexture=D.sourceTexture?D.sourceTexture:null);e.bindTexture(i.TEXTURE_2D_ARRAY,W.__webglTexture,i.TEXTURE0+T)}function Tt(D,T){let W=n.get(D);if(D.isRenderTargetTexture===!1&&D.version>0&&W.__version!==D.version){nt(W,D,T);return}e.bindTexture(i.TEXTURE_3D,W.__webglTexture,i.TEXTURE0+T)}function gt(D,T){let W=n.get(D);if(D.version>0&&W.__version!==D.version){St(W,D,T);return}e.bindTexture(i.TEXTURE_CUBE_MAP,W.__webglTexture,i.TEXTURE0+T)}let Ot={[Go]:i.REPEAT,[si]:i.CLAMP_TO_EDGE,[Wo]:i.MIRRORED_REPEAT},ge={[De]:i.NEAREST,[Ef]:i.NEAREST_MIPMAP_NEAREST,[Ir]:i.NEAREST_MIPMAP_LINEAR,[mn]:i.LINEAR,[yc]:i.LINEAR_MIPMAP_NEAREST,[Ni]:i.LINEAR_MIPMAP_LINEAR},Dt={[Cf]:i.NEVER,[Jh]:i.ALWAYS,[Nf]:i.LESS,[qh]:i.LEQUAL,[Pf]:i.EQUAL,[Yh]:i.GEQUAL,[Lf]:i.GREATER,[Df]:i.NOTEQUAL};function kt(D,T){if(T.type===gn&&t.has("OES_texture_float_linear")===!1&&(T.magFilter===mn||T.magFilter===yc||T.magFilter===Ir||T.magFilter===Ni||T.minFilter===mn||T.minFilter===yc||T.minFilter===Ir||T.minFilter===Ni)&&Ft("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),i.texParameteri(D,i.TEXTURE_WRAP_S,Ot[T.wrapS]),i.texParameteri(D,i.TEXTURE_WRAP_T,Ot[T.wrapT]),(D===i.TEXTURE_3D||D===i.TEXTURE_2D_ARRAY)&&i.texParameteri(D,i.TEXTURE_WRAP_R,Ot[T.wrapR]),i.texParameteri(D,i.TEXTURE_MAG_FILTER,ge[T.magFilter]),i.texParameteri(D,i.TEXTURE_MIN_FILTER,ge[T.minFilter]),T.compareFunction&&(i.texParameteri(D,i.TEXTURE_COMPARE_MODE,i.COMPARE_REF_TO_TEXTURE),i.texParameteri(D,i.TEXTURE_COMPARE_FUNC,Dt[T.compareFunction])),t.has("EXT_texture_filter_anisotropic")===!0){if(T.magFilter===De||T.minFilter!==Ir&&T.minFilter!==Ni||T.type===gn&&t.has("OES_texture_float_linear")===!1)return;if(T.anisotropy>1||n.get(T).__currentAnisotropy){let W=t.get("EXT_texture_filter_anisotropic");i.texParameterf(D,W.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(T.anisotropy,a.getMaxAnisotropy())),n.get(T).__currentAnisotropy=T.anisotropy}}}function Yt(D,T){let W=!1;D.__webglInit===void 0&&(D.__webglInit=!0,T.addEventListener("dispose",I),E(T));let at=T.source,tt=f.get(at);tt===void 0&&(tt={},f.set(at,tt));let lt=Y(T);if(lt!==D.__cacheKey){tt[lt]===void 0&&(tt[lt]={texture:i.createTexture(),usedTimes:0},r.memory.textures++,W=!0),tt[lt].usedTimes++;let ut=tt[D.__cacheKey];ut!==void 0&&(tt[D.__cacheKey].usedTimes--,ut.usedTimes===0&&O(T)),D.__cacheKey=lt,D.__webglTexture=tt[lt].texture}return W}function Xt(D,T,W){return Math.floor(Math.floor(D/W)/T)}function Ae(D,T,W,at){let lt=D.updateRanges;if(lt.length===0)e.texSubImage2D(i.TEXTURE_2D,0,0,0,T.width,T.height,W,at,T.data);else{lt.sort((R,k)=>R.start-k.start);let ut=0;for(let R=1;R<lt.length;R++){let k=lt[ut],H=lt[R],j=k.start+k.count,it=Xt(H.start,T.width,4),st=Xt(k.start,T.width,4);H.start<=j+1&&it===st&&Xt(H.start+H.count-1,T.width,4)===it?k.count=Math.max(k.count,H.start+H.count-k.start):(++ut,lt[ut]=H)}lt.length=ut+1;let $=e.getParameter(i.UNPACK_ROW_LENGTH),J=e.getParameter(i.UNPACK_SKIP_PIXELS),ft=e.getParameter(i.UNPACK_SKIP_ROWS);e.pixelStorei(i.UNPACK_ROW_LENGTH,T.width);for(let R=0,k=lt.length;R<k;R++){let H=lt[R],j=Math.floor(H.start/4),it=Math.ceil(H.count/4),st=j%T.width,_t=Math.floor(j/T.width),Ct=it,ot=1;e.pixelStorei(i.UNPACK_SKIP_PIXELS,st),e.pixelStorei(i.UNPACK_SKIP_ROWS,_t),e.texSubImage2D(i.TEXTURE_2D,0,st,_t,Ct,ot,W,at,T.data)}D.clearUpdateRanges(),e.pixelStorei(i.UNPACK_ROW_LENGTH,$),e.pixelStorei(i.UNPACK_SKIP_PIXELS,J),e.pixelStorei(i.UNPACK_SKIP_ROWS,ft)}}function nt(D,T,W){let at=i.TEXTURE_2D;(T.isDataArrayTexture||T.isCompressedArrayTexture)&&(at=i.TEXTURE_2D_ARRAY),T.isData3DTexture&&(at=i.TEXTURE_3D);let tt=Yt(D,T),lt=T.source;e.bindTexture(at,D.__webglTexture,i.TEXTURE0+W);let ut=n.get(lt);if(lt.version!==ut.__version||tt===!0){if(e.activeTexture(i.TEXTURE0+W),(typeof ImageBitmap<"u"&&T.image instanceof ImageBitmap)===!1){let ot=Kt.getPrimaries(Kt.workingColorSpace),vt=T.colorSpace===Li?null:Kt.getPrimaries(T.colorSpace),Ut=T.colorSpace===Li||ot===vt?i.NONE:i.BROWSER_DEFAULT_WEBGL;e.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,T.flipY),e.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,T.premultiplyAlpha),e.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,Ut)}e.pixelStorei(i.UNPACK_ALIGNMENT,T.unpackAlignment);let J=y(T.image,!1,a.maxTextureSize);J=At(T,J);let ft=s.convert(T.format,T.colorSpace),R=s.convert(T.type),k=S(T.internalFormat,ft,R,T.normalized,T.colorSpace,T.isVideoTexture);kt(at,T);let H,j=T.mipmaps,it=T.isVideoTexture!==!0,st=ut.__version===void 0||tt===!0,_t=lt.dataReady,Ct=M(T,J);if(T.isDepthTexture)k=b(T.format===Pi,T.type),st&&(it?e.texStorage2D(i.TEXTURE_2D,1,k,J.width,J.height):e.texImage2D(i.TEXTURE_2D,0,k,J.width,J.height,0,ft,R,null));else if(T.isDataTexture)if(j.length>0){it&&st&&e.texStorage2D(i.TEXTURE_2D,Ct,k,j[0].width,j[0].height);for(let ot=0,vt=j.length;ot<vt;ot++)H=j[ot],it?_t&&e.texSubImage2D(i.TEXTURE_2D,ot,0,0,H.width,H.height,ft,R,H.data):e.texImage2D(i.TEXTURE_2D,ot,k,H.width,H.height,0,ft,R,H.data);T.generateMipmaps=!1}else it?(st&&e.texStorage2D(i.TEXTURE_2D,Ct,k,J.width,J.height),_t&&Ae(T,J,ft,R)):e.texImage2D(i.TEXTURE_2D,0,k,J.width,J.height,0,ft,R,J.data);else if(T.isCompressedTexture)if(T.isCompressedArrayTexture){it&&st&&e.texStorage3D(i.TEXTURE_2D_ARRAY,Ct,k,j[0].width,j[0].height,J.depth);for(let ot=0,vt=j.length;ot<vt;ot++)if(H=j[ot],T.format!==bn)if(ft!==null)if(it){if(_t)if(T.layerUpdates.size>0){let Ut=sd(H.width,H.height,T.format,T.type);for(let pt of T.layerUpdates){let re=H.data.subarray(pt*Ut/H.data.BYTES_PER_ELEMENT,(pt+1)*Ut/H.data.BYTES_PER_ELEMENT);e.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ot,0,0,pt,H.width,H.height,1,ft,re)}}else e.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ot,0,0,0,H.width,H.height,J.depth,ft,H.data)}else e.compressedTexImage3D(i.TEXTURE_2D_ARRAY,ot,k,H.width,H.height,J.depth,0,H.data,0,0);else Ft("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else it?_t&&e.texSubImage3D(i.TEXTURE_2D_ARRAY,ot,0,0,0,H.width,H.height,J.depth,ft,R,H.data):e.texImage3D(i.TEXTURE_2D_ARRAY,ot,k,H.width,H.height,J.depth,0,ft,R,H.data);T.layerUpdates.size>0&&T.clearLayerUpdates()}else{it&&st&&e.texStorage2D(i.TEXTURE_2D,Ct,k,j[0].width,j[0].height);for(let ot=0,vt=j.length;ot<vt;ot++)H=j[ot],T.format!==bn?ft!==null?it?_t&&e.compressedTexSubImage2D(i.TEXTURE_2D,ot,0,0,H.width,H.height,ft,H.data):e.compressedTexImage2D(i.TEXTURE_2D,ot,k,H.width,H.height,0,H.data):Ft("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):it?_t&&e.texSubImage2D(i.TEXTURE_2D,ot,0,0,H.width,H.height,ft,R,H.data):e.texImage2D(i.TEXTURE_2D,ot,k,H.width,H.height,0,ft,R,H.data)}else if(T.isDataArrayTexture)if(it){if(st&&e.texStorage3D(i.TEXTURE_2D_ARRAY,Ct,k,J.width,J.height,J.depth),_t)if(T.layerUpdates.size>0){let ot=sd(J.width,J.height,T.format,T.type);for(let vt of T.layerUpdates){let Ut=J.data.subarray(vt*ot/J.data.BYTES_PER_ELEMENT,(vt+1)*ot/J.data.BYTES_PER_ELEMENT);e.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,vt,J.width,J.height,1,ft,R,Ut)}T.clearLayerUpdates()}else e.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,0,J.width,J.height,J.depth,ft,R,J.data)}else e.texImage3D(i.TEXTURE_2D_ARRAY,0,k,J.width,J.height,J.depth,0,ft,R,J.data);else if(T.isData3DTexture)it?(st&&e.texStorage3D(i.TEXTURE_3D,Ct,k,J.width,J.height,J.depth),_t&&e.texSubImage3D(i.TEXTURE_3D,0,0,0,0,J.width,J.height,J.depth,ft,R,J.data)):e.texImage3D(i.TEXTURE_3D,0,k,J.width,J.height,J.depth,0,ft,R,J.data);else if(T.isFramebufferTexture){if(st)if(it)e.texStorage2D(i.TEXTURE_2D,Ct,k,J.width,J.height);else{let ot=J.width,vt=J.height;for(let Ut=0;Ut<Ct;Ut++)e.texImage2D(i.TEXTURE_2D,Ut,k,ot,vt,0,ft,R,null),ot>>=1,vt>>=1}}else if(T.isHTMLTexture){if("texElementImage2D"in i){let ot=i.canvas;if(ot.hasAttribute("layoutsubtree")||ot.setAttribute("layoutsubtree","true"),J.parentNode!==ot){ot.appendChild(J),u.add(T),ot.onpaint=vt=>{let Ut=vt.changedElements;for(let pt of u)Ut.includes(pt.image)&&(pt.needsUpdate=!0)},ot.requestPaint();return}if(i.texElementImage2D.length===3)i.texElementImage2D(i.TEXTURE_2D,i.RGBA8,J);else{let Ut=i.RGBA,pt=i.RGBA,re=i.UNSIGNED_BYTE;i.texElementImage2D(i.TEXTURE_2D,0,Ut,pt,re,J)}i.texParameteri(i.TEXTURE_2D,i.TEXTURE_MIN_FILTER,i.LINEAR),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_S,i.CLAMP_TO_EDGE),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_T,i.CLAMP_TO_EDGE)}}else if(j.length>0){if(it&&st){let ot=Lt(j[0]);e.texStorage2D(i.TEXTURE_2D,Ct,k,ot.width,ot.height)}for(let ot=0,vt=j.length;ot<vt;ot++)H=j[ot],it?_t&&e.texSubImage2D(i.TEXTURE_2D,ot,0,0,ft,R,H):e.texImage2D(i.TEXTURE_2D,ot,k,ft,R,H);T.generateMipmaps=!1}else if(it){if(st){let ot=Lt(J);e.texStorage2D(i.TEXTURE_2D,Ct,k,ot.width,ot.height)}_t&&e.texSubImage2D(i.TEXTURE_2D,0,0,0,ft,R,J)}else e.texImage2D(i.TEXTURE_2D,0,k,ft,R,J);w(T)&&T.mipmapsAutoUpdate===!0&&p(at),ut.__version=lt.version,T.onUpdate&&T.onUpdate(T)}D.__version=T.version}function St(D,T,W){if(T.image.length!==6)return;let at=Yt(D,T),tt=T.source;e.bindTexture(i.TEXTURE_CUBE_MAP,D.__webglTexture,i.TEXTURE0+W);let lt=n.get(tt);if(tt.version!==lt.__version||at===!0){e.activeTexture(i.TEXTURE0+W);let ut=Kt.getPrimaries(Kt.workingColorSpace),$=T.colorSpace===Li?null:Kt.getPrimaries(T.colorSpace),J=T.colorSpace===Li||ut===$?i.NONE:i.BROWSER_DEFAULT_WEBGL;e.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,T.flipY),e.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,T.premultiplyAlpha),e.pixelStorei(i.UNPACK_ALIGNMENT,T.unpackAlignment),e.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,J);let ft=T.isCompressedTexture||T.image[0].isCompressedTexture,R=T.image[0]&&T.image[0].isDataTexture,k=[];for(let pt=0;pt<6;pt++)!ft&&!R?k[pt]=y(T.image[pt],!0,a.maxCubemapSize):k[pt]=R?T.image[pt].image:T.image[pt],k[pt]=At(T,k[pt]);let H=k[0],j=s.convert(T.format,T.colorSpace),it=s.convert(T.type),st=S(T.internalFormat,j,it,T.normalized,T.colorSpace),_t=T.isVideoTexture!==!0,Ct=lt.__version===void 0||at===!0,ot=tt.dataReady,vt=M(T,H);kt(i.TEXTURE_CUBE_MAP,T);let Ut;if(T.isDepthTexture){if(st=b(T.format===Pi,T.type),Ct)if(_t)e.texStorage2D(i.TEXTURE_CUBE_MAP,1,st,H.width,H.height);else for(let pt=0;pt<6;pt++)e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,0,st,H.width,H.height,0,j,it,null)}else if(ft){_t&&Ct&&e.texStorage2D(i.TEXTURE_CUBE_MAP,vt,st,H.width,H.height);for(let pt=0;pt<6;pt++){Ut=k[pt].mipmaps;for(let re=0;re<Ut.length;re++){let Te=Ut[re];T.format!==bn?j!==null?_t?ot&&e.compressedTexSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,re,0,0,Te.width,Te.height,j,Te.data):e.compressedTexImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,re,st,Te.width,Te.height,0,Te.data):Ft("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):_t?ot&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,re,0,0,Te.width,Te.height,j,it,Te.data):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,re,st,Te.width,Te.height,0,j,it,Te.data)}}}else{if(Ut=T.mipmaps,_t&&Ct){Ut.length>0&&vt++;let pt=Lt(k[0]);e.texStorage2D(i.TEXTURE_CUBE_MAP,vt,st,pt.width,pt.height)}for(let pt=0;pt<6;pt++)if(R){_t?ot&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,0,0,0,k[pt].width,k[pt].height,j,it,k[pt].data):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,0,st,k[pt].width,k[pt].height,0,j,it,k[pt].data);for(let re=0;re<Ut.length;re++){let Gn=Ut[re].image[pt].image;_t?ot&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,re+1,0,0,Gn.width,Gn.height,j,it,Gn.data):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,re+1,st,Gn.width,Gn.height,0,j,it,Gn.data)}}else{_t?ot&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,0,0,0,j,it,k[pt]):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,0,st,j,it,k[pt]);for(let re=0;re<Ut.length;re++){let Te=Ut[re];_t?ot&&e.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,re+1,0,0,j,it,Te.image[pt]):e.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+pt,re+1,st,j,it,Te.image[pt])}}}w(T)&&T.mipmapsAutoUpdate===!0&&p(i.TEXTURE_CUBE_MAP),lt.__version=tt.version,T.onUpdate&&T.onUpdate(T)}D.__version=T.version}function wt(D,T,W,at,tt,lt){let ut=s.convert(W.format,W.colorSpace),$=s.convert(W.type),J=S(W.internalFormat,ut,$,W.normalized,W.colorSpace),ft=n.get(T),R=n.get(W);if(R.__renderTarget=T,!ft.__hasExternalTextures){let k=Math.max(1,T.width>>lt),H=Math.max(1,T.height>>lt);tt===i.TEXTURE_3D||tt===i.TEXTURE_2D_ARRAY?e.texImage3D(tt,lt,J,k,H,T.depth,0,ut,$,null):e.texImage2D(tt,lt,J,k,H,0,ut,$,null)}e.bindFramebuffer(i.FRAMEBUFFER,D),dt(T)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,at,tt,R.__webglTexture,0,Jt(T)):(tt===i.TEXTURE_2D||tt>=i.TEXTURE_CUBE_MAP_POSITIVE_X&&tt<=i.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&i.framebufferTexture2D(i.FRAMEBUFFER,at,tt,R.__webglTexture,lt),e.bindFramebuffer(i.FRAMEBUFFER,null)}function Qt(D,T,W){if(i.bindRenderbuffer(i.RENDERBUFFER,D),T.depthBuffer){let at=T.depthTexture,tt=at&&at.isDepthTexture?at.type:null,lt=b(T.stencilBuffer,tt),ut=T.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;dt(T)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,Jt(T),lt,T.width,T.height):W?i.renderbufferStorageMultisample(i.RENDERBUFFER,Jt(T),lt,T.width,T.height):i.renderbufferStorage(i.RENDERBUFFER,lt,T.width,T.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,ut,i.RENDERBUFFER,D)}else{let at=T.textures;for(let tt=0;tt<at.length;tt++){let lt=at[tt],ut=s.convert(lt.format,lt.colorSpace),$=s.convert(lt.type),J=S(lt.internalFormat,ut,$,lt.normalized,lt.colorSpace);dt(T)?o.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,Jt(T),J,T.width,T.height):W?i.renderbufferStorageMultisample(i.RENDERBUFFER,Jt(T),J,T.width,T.height):i.renderbufferStorage(i.RENDERBUFFER,J,T.width,T.height)}}i.bindRenderbuffer(i.RENDERBUFFER,null)}function Ht(D,T,W){let at=T.isWebGLCubeRenderTarget===!0;if(e.bindFramebuffer(i.FRAMEBUFFER,D),!(T.depthTexture&&T.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");let tt=n.get(T.depthTexture);tt.__renderTarget=T;let lt=at?T.depthTexture.image[0]:T.depthTexture.image;(!tt.__webglTexture||lt.width!==T.width||lt.height!==T.height)&&(lt.width=T.width,lt.height=T.height,T.depthTexture.needsUpdate=!0),at?gt(T.depthTexture,0):ct(T.depthTexture,0);let ut=tt.__webglTexture,$=Jt(T),J=at?i.TEXTURE_CUBE_MAP_POSITIVE_X+W:i.TEXTURE_2D,ft=T.depthTexture.format===Pi?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;if(T.depthTexture.format===Ti)dt(T)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,ft,J,ut,0,$):i.framebufferTexture2D(i.FRAMEBUFFER,ft,J,ut,0);else if(T.depthTexture.format===Pi)dt(T)?o.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,ft,J,ut,0,$):i.framebufferTexture2D(i.FRAMEBUFFER,ft,J,ut,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function be(D){let T=n.get(D),W=D.isWebGLCubeRenderTarget===!0;if(T.__boundDepthTexture!==D.depthTexture){let at=D.depthTexture;if(T.__depthDisposeCallback&&T.__depthDisposeCallback(),at){let tt=()=>{delete T.__boundDepthTexture,delete T.__depthDisposeCallback,at.removeEventListener("dispose",tt)};at.addEventListener("dispose",tt),T.__depthDisposeCallback=tt}T.__boundDepthTexture=at}if(D.depthTexture&&!T.__autoAllocateDepthBuffer)if(W)for(let at=0;at<6;at++)Ht(T.__webglFramebuffer[at],D,at);else D.texture.mipmaps.length>0?Ht(T.__webglFramebuffer[0],D,0):Ht(T.__webglFramebuffer,D,0);else if(W){T.__webglDepthbuffer=[];for(let at=0;at<6;at++)if(e.bindFramebuffer(i.FRAMEBUFFER,T.__webglFramebuffer[at]),T.__webglDepthbuffer[at]===void 0)T.__webglDepthbuffer[at]=i.createRenderbuffer(),Qt(T.__webglDepthbuffer[at],D,!1);else{let tt=D.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,lt=T.__webglDepthbuffer[at];i.bindRenderbuffer(i.RENDERBUFFER,lt),i.framebufferRenderbuffer(i.FRAMEBUFFER,tt,i.RENDERBUFFER,lt)}}else if(D.texture.mipmaps.length>0?e.bindFramebuffer(i.FRAMEBUFFER,T.__webglFramebuffer[0]):e.bindFramebuffer(i.FRAMEBUFFER,T.__webglFramebuffer),T.__webglDepthbuffer===void 0)T.__webglDepthbuffer=i.createRenderbuffer(),Qt(T.__webglDepthbuffer,D,!1);else{let tt=D.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,lt=T.__webglDepthbuffer;i.bindRenderbuffer(i.RENDERBUFFER,lt),i.framebufferRenderbuffer(i.FRAMEBUFFER,tt,i.RENDERBUFFER,lt)}e.bindFramebuffer(i.FRAMEBUFFER,null)}function fe(D,T,W){let at=n.get(D);T!==void 0&&wt(at.__webglFramebuffer,D,D.texture,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,0),W!==void 0&&be(D)}function ne(D){let T=D.texture,W=n.get(D),at=n.get(T);D.addEventListener("dispose",N),E(D);let tt=D.textures,lt=D.isWebGLCubeRenderTarget===!0,ut=tt.length>1;if(ut||(at.__webglTexture===void 0&&(at.__webglTexture=i.createTexture()),at.__version=T.version,r.memory.textures++),lt){W.__webglFramebuffer=[];for(let $=0;$<6;$++)if(T.mipmaps.length>0){W.__webglFramebuffer[$]=[];for(let J=0;J<T.mipmaps.length;J++)W.__webglFramebuffer[$][J]=i.createFramebuffer()}else W.__webglFramebuffer[$]=i.createFramebuffer()}else{if(T.mipmaps.length>0){W.__webglFramebuffer=[];for(let $=0;$<T.mipmaps.length;$++)W.__webglFramebuffer[$]=i.createFramebuffer()}else W.__webglFramebuffer=i.createFramebuffer();if(ut)for(let $=0,J=tt.length;$<J;$++){let ft=n.get(tt[$]);ft.__webglTexture===void 0&&(ft.__webglTexture=i.createTexture(),r.memory.textures++)}if(D.samples>0&&dt(D)===!1){W.__webglMultisampledFramebuffer=i.createFramebuffer(),W.__webglColorRenderbuffer=[],e.bindFramebuffer(i.FRAMEBUFFER,W.__webglMultisampledFramebuffer);for(let $=0;$<tt.length;$++){let J=tt[$];W.__webglColorRenderbuffer[$]=i.createRenderbuffer(),i.bindRenderbuffer(i.RENDERBUFFER,W.__webglColorRenderbuffer[$]);let ft=s.convert(J.format,J.colorSpace),R=s.convert(J.type),k=S(J.internalFormat,ft,R,J.normalized,J.colorSpace,D.isXRRenderTarget===!0),H=Jt(D);i.renderbufferStorageMultisample(i.RENDERBUFFER,H,k,D.width,D.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+$,i.RENDERBUFFER,W.__webglColorRenderbuffer[$])}i.bindRenderbuffer(i.RENDERBUFFER,null),D.depthBuffer&&(W.__webglDepthRenderbuffer=i.createRenderbuffer(),Qt(W.__webglDepthRenderbuffer,D,!0)),e.bindFramebuffer(i.FRAMEBUFFER,null)}}if(lt){e.bindTexture(i.TEXTURE_CUBE_MAP,at.__webglTexture),kt(i.TEXTURE_CUBE_MAP,T);for(let $=0;$<6;$++)if(T.mipmaps.length>0)for(let J=0;J<T.mipmaps.length;J++)wt(W.__webglFramebuffer[$][J],D,T,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+$,J);else wt(W.__webglFramebuffer[$],D,T,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+$,0);w(T)?p(i.TEXTURE_CUBE_MAP):T.mipmaps.length>0&&i.texParameteri(i.TEXTURE_CUBE_MAP,i.TEXTURE_MAX_LEVEL,T.mipmaps.length-1),e.unbindTexture()}else if(ut){for(let $=0,J=tt.length;$<J;$++){let ft=tt[$],R=n.get(ft),k=i.TEXTURE_2D;(D.isWebGL3DRenderTarget||D.isWebGLArrayRenderTarget)&&(k=D.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),e.bindTexture(k,R.__webglTexture),kt(k,ft),wt(W.__webglFramebuffer,D,ft,i.COLOR_ATTACHMENT0+$,k,0),w(ft)&&p(k)}e.unbindTexture()}else{let $=i.TEXTURE_2D;if((D.isWebGL3DRenderTarget||D.isWebGLArrayRenderTarget)&&($=D.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),e.bindTexture($,at.__webglTexture),kt($,T),T.mipmaps.length>0)for(let J=0;J<T.mipmaps.length;J++)wt(W.__webglFramebuffer[J],D,T,i.COLOR_ATTACHMENT0,$,J);else wt(W.__webglFramebuffer,D,T,i.COLOR_ATTACHMENT0,$,0);w(T)?p($):T.mipmaps.length>0&&i.texParameteri($,i.TEXTURE_MAX_LEVEL,T.mipmaps.length-1),e.unbindTexture()}D.depthBuffer&&be(D)}function B(D){let T=D.textures;for(let W=0,at=T.length;W<at;W++){let tt=T[W];if(w(tt)&&tt.mipmapsAutoUpdate===!0){let lt=_(D),ut=n.get(tt).__webglTexture;e.bindTexture(lt,ut),p(lt),e.unbindTexture()}}}let Ee=[];function $t(D){if(D.samples>0){if(dt(D)===!1){let T=D.textures,W=D.width,at=D.height,tt=i.COLOR_BUFFER_BIT,lt=D.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,ut=n.get(D),$=T.length>1;if($)for(let ft=0;ft<T.length;ft++)e.bindFramebuffer(i.FRAMEBUFFER,ut.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+ft,i.RENDERBUFFER,null),e.bindFramebuffer(i.FRAMEBUFFER,ut.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+ft,i.TEXTURE_2D,null,0);e.bindFramebuffer(i.READ_FRAMEBUFFER,ut.__webglMultisampledFramebuffer),D.texture.mipmaps.length>0?e.bindFramebuffer(i.DRAW_FRAMEBUFFER,ut.__webglFramebuffer[0]):e.bindFramebuffer(i.DRAW_FRAMEBUFFER,ut.__webglFramebuffer);for(let ft=0;ft<T.length;ft++){if(D.resolveDepthBuffer&&(D.depthBuffer&&(tt|=i.DEPTH_BUFFER_BIT),D.stencilBuffer&&D.resolveStencilBuffer&&(tt|=i.STENCIL_BUFFER_BIT)),$){i.framebufferRenderbuffer(i.READ_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.RENDERBUFFER,ut.__webglColorRenderbuffer[ft]);let R=n.get(T[ft]).__webglTexture;i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,R,0)}i.blitFramebuffer(0,0,W,at,0,0,W,at,tt,i.NEAREST),c===!0&&(Ee.length=0,Ee.push(i.COLOR_ATTACHMENT0+ft),D.depthBuffer&&D.storeMultisampledDepthBuffer===!1&&Ee.push(lt),i.invalidateFramebuffer(i.READ_FRAMEBUFFER,Ee))}if(e.bindFramebuffer(i.READ_FRAMEBUFFER,null),e.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),$)for(let ft=0;ft<T.length;ft++){e.bindFramebuffer(i.FRAMEBUFFER,ut.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+ft,i.RENDERBUFFER,ut.__webglColorRenderbuffer[ft]);let R=n.get(T[ft]).__webglTexture;e.bindFramebuffer(i.FRAMEBUFFER,ut.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+ft,i.TEXTURE_2D,R,0)}e.bindFramebuffer(i.DRAW_FRAMEBUFFER,ut.__webglMultisampledFramebuffer)}else if(D.depthBuffer&&D.storeMultisampledDepthBuffer===!1&&c){let T=D.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;i.invalidateFramebuffer(i.DRAW_FRAMEBUFFER,[T])}}}function Jt(D){return Math.min(a.maxSamples,D.samples)}function dt(D){let T=n.get(D);return D.samples>0&&t.has("WEBGL_multisampled_render_to_texture")===!0&&T.__useRenderToTexture!==!1}function se(D){let T=r.render.frame;h.get(D)!==T&&(h.set(D,T),D.update())}function At(D,T){let W=D.colorSpace,at=D.format,tt=D.type;return D.isCompressedTexture===!0||D.isVideoTexture===!0||W!==Ks&&W!==Li&&(Kt.getTransfer(W)===pe?(at!==bn||tt!==an)&&Ft("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):zt("WebGLTextures: Unsupported texture color space:",W)),T}function Lt(D){return typeof HTMLImageElement<"u"&&D instanceof HTMLImageElement?(l.width=D.naturalWidth||D.width,l.height=D.naturalHeight||D.height):typeof VideoFrame<"u"&&D instanceof VideoFrame?(l.width=D.displayWidth,l.height=D.displayHeight):(l.width=D.width,l.height=D.height),l}this.allocateTextureUnit=Pt,this.resetTextureUnits=Z,this.getTextureUnits=et,this.setTextureUnits=ht,this.setTexture2D=ct,this.setTexture2DArray=mt,this.setTexture3D=Tt,this.setTextureCube=gt,this.rebindTextures=fe,this.setupRenderTarget=ne,this.updateRenderTargetMipmap=B,this.updateMultisampleRenderTarget=$t,this.setupDepthRenderbuffer=be,this.setupFrameBufferTexture=wt,this.useMultisampledRTT=dt,this.dispose=U}function iv(i,t){function e(n,a=Li){let s,r=Kt.getTransfer(a);if(n===an)return i.UNSIGNED_BYTE;if(n===_c)return i.UNSIGNED_SHORT_4_4_4_4;if(n===vc)return i.UNSIGNED_SHORT_5_5_5_1;if(n===Gh)return i.UNSIGNED_INT_5_9_9_9_REV;if(n===Wh)return i.UNSIGNED_INT_10F_11F_11F_REV;if(n===Rr)return i.BYTE;if(n===Cr)return i.SHORT;if(n===Yi)return i.UNSIGNED_SHORT;if(n===ds)return i.INT;if(n===An)return i.UNSIGNED_INT;if(n===gn)return i.FLOAT;if(n===Zn)return i.HALF_FLOAT;if(n===jh)return i.ALPHA;if(n===Xh)return i.RGB;if(n===bn)return i.RGBA;if(n===Ti)return i.DEPTH_COMPONENT;if(n===Pi)return i.DEPTH_STENCIL;if(n===Nr)return i.RED;if(n===Sa)return i.RED_INTEGER;if(n===hi)return i.RG;if(n===us)return i.RG_INTEGER;if(n===fs)return i.RGBA_INTEGER;if(n===Pr||n===Lr||n===Dr||n===Ur)if(r===pe)if(s=t.get("WEBGL_compressed_texture_s3tc_srgb"),s!==null){if(n===Pr)return s.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(n===Lr)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(n===Dr)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(n===Ur)return s.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(s=t.get("WEBGL_compressed_texture_s3tc"),s!==null){if(n===Pr)return s.COMPRESSED_RGB_S3TC_DXT1_EXT;if(n===Lr)return s.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(n===Dr)return s.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(n===Ur)return s.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(n===Mc||n===Sc||n===wc||n===Ac)if(s=t.get("WEBGL_compressed_texture_pvrtc"),s!==null){if(n===Mc)return s.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(n===Sc)return s.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(n===wc)return s.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(n===Ac)return s.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(n===Ec||n===Tc||n===Ic||n===Rc||n===Cc||n===Or||n===Nc)if(s=t.get("WEBGL_compressed_texture_etc"),s!==null){if(n===Ec||n===Tc)return r===pe?s.COMPRESSED_SRGB8_ETC2:s.COMPRESSED_RGB8_ETC2;if(n===Ic)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:s.COMPRESSED_RGBA8_ETC2_EAC;if(n===Rc)return s.COMPRESSED_R11_EAC;if(n===Cc)return s.COMPRESSED_SIGNED_R11_EAC;if(n===Or)return s.COMPRESSED_RG11_EAC;if(n===Nc)return s.COMPRESSED_SIGNED_RG11_EAC}else return null;if(n===Pc||n===Lc||n===Dc||n===Uc||n===Oc||n===Fc||n===Bc||n===kc||n===zc||n===Vc||n===Hc||n===Gc||n===Wc||n===jc)if(s=t.get("WEBGL_compressed_texture_astc"),s!==null){if(n===Pc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:s.COMPRESSED_RGBA_ASTC_4x4_KHR;if(n===Lc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:s.COMPRESSED_RGBA_ASTC_5x4_KHR;if(n===Dc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:s.COMPRESSED_RGBA_ASTC_5x5_KHR;if(n===Uc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:s.COMPRESSED_RGBA_ASTC_6x5_KHR;if(n===Oc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:s.COMPRESSED_RGBA_ASTC_6x6_KHR;if(n===Fc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:s.COMPRESSED_RGBA_ASTC_8x5_KHR;if(n===Bc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:s.COMPRESSED_RGBA_ASTC_8x6_KHR;if(n===kc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:s.COMPRESSED_RGBA_ASTC_8x8_KHR;if(n===zc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:s.COMPRESSED_RGBA_ASTC_10x5_KHR;if(n===Vc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:s.COMPRESSED_RGBA_ASTC_10x6_KHR;if(n===Hc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:s.COMPRESSED_RGBA_ASTC_10x8_KHR;if(n===Gc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:s.COMPRESSED_RGBA_ASTC_10x10_KHR;if(n===Wc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:s.COMPRESSED_RGBA_ASTC_12x10_KHR;if(n===jc)return r===pe?s.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:s.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(n===Xc||n===qc||n===Yc)if(s=t.get("EXT_texture_compression_bptc"),s!==null){if(n===Xc)return r===pe?s.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:s.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(n===qc)return s.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(n===Yc)return s.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(n===Jc||n===Kc||n===Fr||n===Zc)if(s=t.get("EXT_texture_compression_rgtc"),s!==null){if(n===Jc)return s.COMPRESSED_RED_RGTC1_EXT;if(n===Kc)return s.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(n===Fr)return s.COMPRESSED_RED_GREEN_RGTC2_EXT;if(n===Zc)return s.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return n===Ma?i.UNSIGNED_INT_24_8:i[n]!==void 0?i[n]:null}return{convert:e}}function ov(i,t){function e(m,g){m.matrixAutoUpdate===!0&&m.updateMatrix(),g.value.copy(m.matrix)}function n(m,g){g.color.getRGB(m.fogColor.value,nd(i)),g.isFog?(m.fogNear.value=g.near,m.fogFar.value=g.far):g.isFogExp2&&(m.fogDensity.value=g.density)}function a(m,g,y,w,p){g.isNodeMaterial?g.uniformsNeedUpdate=!1:g.isMeshBasicMaterial?s(m,g):g.isMeshLambertMaterial?(s(m,g),g.envMap&&(m.envMapIntensity.value=g.envMapIntensity)):g.isMeshToonMaterial?(s(m,g),u(m,g)):g.isMeshPhongMaterial?(s(m,g),h(m,g),g.envMap&&(m.envMapIntensity.value=g.envMapIntensity)):g.isMeshStandardMaterial?(s(m,g),d(m,g),g.isMeshPhysicalMaterial&&f(m,g,p)):g.isMeshMatcapMaterial?(s(m,g),x(m,g)):g.isMeshDepthMaterial?s(m,g):g.isMeshDistanceMaterial?(s(m,g),v(m,g)):g.isMeshNormalMaterial?s(m,g):g.isLineBasicMaterial?(r(m,g),g.isLineDashedMaterial&&o(m,g)):g.isPointsMaterial?c(m,g,y,w):g.isSpriteMaterial?l(m,g):g.isShadowMaterial?(m.color.value.copy(g.color),m.opacity.value=g.opacity):g.isShaderMaterial&&(g.uniformsNeedUpdate=!1)}function s(m,g){m.opacity.value=g.opacity,g.color&&m.diffuse.value.copy(g.color),g.emissive&&m.emissive.value.copy(g.emissive).multiplyScalar(g.emissiveIntensity),g.map&&(m.map.value=g.map,e(g.map,m.mapTransform)),g.alphaMap&&(m.alphaMap.value=g.alphaMap,e(g.alphaMap,m.alphaMapTransform)),g.bumpMap&&(m.bumpMap.value=g.bumpMap,e(g.bumpMap,m.bumpMapTransform),m.bumpScale.value=g.bumpScale,g.side===je&&(m.bumpScale.value*=-1)),g.normalMap&&(m.normalMap.value=g.normalMap,e(g.normalMap,m.normalMapTransform),m.normalScale.value.copy(g.normalScale),g.side===je&&m.normalScale.value.negate()),g.displacementMap&&(m.displacementMap.value=g.displacementMap,e(g.displacementMap,m.displacementMapTransform),m.displacementScale.value=g.displacementScale,m.displacementBias.value=g.displacementBias),g.emissiveMap&&(m.emissiveMap.value=g.emissiveMap,e(g.emissiveMap,m.emissiveMapTransform)),g.specularMap&&(m.specularMap.value=g.specularMap,e(g.specularMap,m.specularMapTransform)),g.alphaTest>0&&(m.alphaTest.value=g.alphaTest);let y=t.get(g),w=y.envMap,p=y.envMapRotation;w&&(m.envMap.value=w,m.envMapRotation.value.setFromMatrix4(rv.makeRotationFromEuler(p)).transpose(),w.isCubeTexture&&w.isRenderTargetTexture===!1&&m.envMapRotation.value.premultiply(yp),m.reflectivity.value=g.reflectivity,m.ior.value=g.ior,m.refractionRatio.value=g.refractionRatio),g.lightMap&&(m.lightMap.value=g.lightMap,m.lightMapIntensity.value=g.lightMapIntensity,e(g.lightMap,m.lightMapTransform)),g.aoMap&&(m.aoMap.value=g.aoMap,m.aoMapIntensity.value=g.aoMapIntensity,e(g.aoMap,m.aoMapTransform))}function r(m,g){m.diffuse.value.copy(g.color),m.opacity.value=g.opacity,g.map&&(m.map.value=g.map,e(g.map,m.mapTransform))}function o(m,g){m.dashSize.value=g.dashSize,m.totalSize.value=g.dashSize+g.gapSize,m.scale.value=g.scale}function c(m,g,y,w){m.diffuse.value.copy(g.color),m.opacity.value=g.opacity,m.size.value=g.size*y,m.scale.value=w*.5,g.map&&(m.map.value=g.map,e(g.map,m.uvTransform)),g.alphaMap&&(m.alphaMap.value=g.alphaMap,e(g.alphaMap,m.alphaMapTransform)),g.alphaTest>0&&(m.alphaTest.value=g.alphaTest)}function l(m,g){m.diffuse.value.copy(g.color),m.opacity.value=g.opacity,m.rotation.value=g.rotation,g.map&&(m.map.value=g.map,e(g.map,m.mapTransform)),g.alphaMap&&(m.alphaMap.value=g.alphaMap,e(g.alphaMap,m.alphaMapTransform)),g.alphaTest>0&&(m.alphaTest.value=g.alphaTest)}function h(m,g){m.specular.value.copy(g.specular),m.shininess.value=Math.max(g.shininess,1e-4)}function u(m,g){g.gradientMap&&(m.gradientMap.value=g.gradientMap)}function d(m,g){m.metalness.value=g.metalness,g.metalnessMap&&(m.metalnessMap.value=g.metalnessMap,e(g.metalnessMap,m.metalnessMapTransform)),m.roughness.value=g.roughness,g.roughnessMap&&(m.roughnessMap.value=g.roughnessMap,e(g.roughnessMap,m.roughnessMapTransform)),g.envMap&&(m.envMapIntensity.value=g.envMapIntensity)}function f(m,g,y){m.ior.value=g.ior,g.diffuseRoughness>0&&(m.diffuseRoughness.value=g.diffuseRoughness,g.diffuseRoughnessMap&&(m.diffuseRoughnessMap.value=g.diffuseRoughnessMap,e(g.diffuseRoughnessMap,m.diffuseRoughnessMapTransform))),g.sheen>0&&(m.sheenColor.value.copy(g.sheenColor).multiplyScalar(g.sheen),m.sheenRoughness.value=g.sheenRoughness,g.sheenColorMap&&(m.sheenColorMap.value=g.sheenColorMap,e(g.sheenColorMap,m.sheenColorMapTransform)),g.sheenRoughnessMap&&(m.sheenRoughnessMap.value=g.sheenRoughnessMap,e(g.sheenRoughnessMap,m.sheenRoughnessMapTransform))),g.clearcoat>0&&(m.clearcoat.value=g.clearcoat,m.clearcoatRoughness.value=g.clearcoatRoughness,g.clearcoatMap&&(m.clearcoatMap.value=g.clearcoatMap,e(g.clearcoatMap,m.clearcoatMapTransform)),g.clearcoatRoughnessMap&&(m.clearcoatRoughnessMap.value=g.clearcoatRoughnessMap,e(g.clearcoatRoughnessMap,m.clearcoatRoughnessMapTransform)),g.clearcoatNormalMap&&(m.clearcoatNormalMap.value=g.clearcoatNormalMap,e(g.clearcoatNormalMap,m.clearcoatNormalMapTransform),m.clearcoatNormalScale.value.copy(g.clearcoatNormalScale),g.side===je&&m.clearcoatNormalScale.value.negate())),g.dispersion>0&&(m.dispersion.value=g.dispersion),g.retroreflectivity>0&&(m.retroreflectivity.value=g.retroreflectivity),g.iridescence>0&&(m.iridescence.value=g.iridescence,m.iridescenceIOR.value=g.iridescenceIOR,m.iridescenceThicknessMinimum.value=g.iridescenceThicknessMinimum,m.iridescenceThicknessMaximum.value=g.iridescenceThicknessMaximum,g.iridescenceMap&&(m.iridescenceMap.value=g.iridescenceMap,e(g.iridescenceMap,m.iridescenceMapTransform)),g.iridescenceThicknessMap&&(m.iridescenceThicknessMap.value=g.iridescenceThicknessMap,e(g.iridescenceThicknessMap,m.iridescenceThicknessMapTransform))),g.transmission>0&&(m.transmission.value=g.transmission,m.transmissionSamplerMap.value=y.texture,m.transmissionSamplerSize.value.set(y.width,y.height),g.transmissionMap&&(m.transmissionMap.value=g.transmissionMap,e(g.transmissionMap,m.transmissionMapTransform)),m.thickness.value=g.thickness,g.thicknessMap&&(m.thicknessMap.value=g.thicknessMap,e(g.thicknessMap,m.thicknessMapTransform)),m.attenuationDistance.value=g.attenuationDistance,m.attenuationColor.value.copy(g.attenuationColor)),g.anisotropy>0&&(m.anisotropyVector.value.set(g.anisotropy*Math.cos(g.anisotropyRotation),g.anisotropy*Math.sin(g.anisotropyRotation)),g.anisotropyMap&&(m.anisotropyMap.value=g.anisotropyMap,e(g.anisotropyMap,m.anisotropyMapTransform))),m.specularIntensity.value=g.specularIntensity,m.specularColor.value.copy(g.specularColor),g.specularColorMap&&(m.specularColorMap.value=g.specularColorMap,e(g.specularColorMap,m.specularColorMapTransform)),g.specularIntensityMap&&(m.specularIntensityMap.value=g.specularIntensityMap,e(g.specularIntensityMap,m.specularIntensityMapTransform))}function x(m,g){g.matcap&&(m.matcap.value=g.matcap)}function v(m,g){let y=t.get(g).light;m.referencePosition.value.setFromMatrixPosition(y.matrixWorld),m.nearDistance.value=y.shadow.camera.near,m.farDistance.value=y.shadow.camera.far}return{refreshFogUniforms:n,refreshMaterialUniforms:a}}function cv(i,t,e,n){let a={},s={};function r(y,w){let p=w.program;n.uniformBlockBinding(y,p,a[y.id])}function o(y,w){let p=a[y.id];p===void 0&&(x(y),p=c(y),a[y.id]=p,y.addEventListener("dispose",m));let _=w.program;n.updateUBOMapping(y,_);let S=t.render.frame;s[y.id]!==S&&(l(y),s[y.id]=S)}function c(y){let w=i.createBuffer(),p=y.__size,_=y.usage;return i.bindBuffer(i.UNIFORM_BUFFER,w),i.bufferData(i.UNIFORM_BUFFER,p,_),i.bindBuffer(i.UNIFORM_BUFFER,null),w}function l(y){let w=a[y.id],p=y.uniforms,_=y.__cache;i.bindBuffer(i.UNIFORM_BUFFER,w);for(let S=0,b=p.length;S<b;S++){let M=p[S];if(Array.isArray(M))for(let E=0,A=M.length;E<A;E++)h(M[E],S,E,_);else h(M,S,0,_)}i.bindBuffer(i.UNIFORM_BUFFER,null)}function h(y,w,p,_){if(d(y,w,p,_)===!0){let S=y.__offset,b=y.value;if(Array.isArray(b)){let M=0;for(let E=0;E<b.length;E++){let A=b[E],I=v(A,!0);u(A,y.__data,M),M+=I.storage/Float32Array.BYTES_PER_ELEMENT}}else u(b,y.__data,0);i.bufferSubData(i.UNIFORM_BUFFER,S,y.__data)}}function u(y,w,p){typeof y=="number"||typeof y=="boolean"?w[p]=y:y.isMatrix3?(w[p]=y.elements[0],w[p+1]=y.elements[1],w[p+2]=y.elements[2],w[p+3]=0,w[p+4]=y.elements[3],w[p+5]=y.elements[4],w[p+6]=y.elements[5],w[p+7]=0,w[p+8]=y.elements[6],w[p+9]=y.elements[7],w[p+10]=y.elements[8],w[p+11]=0):ArrayBuffer.isView(y)?w.set(y.subarray(0,w.length-p),p):y.toArray(w,p)}function d(y,w,p,_){let S=y.value,b=w+"_"+p;if(Array.isArray(S)){_[b]===void 0&&(_[b]=[]);let M=_[b],E=!1;for(let A=0;A<S.length;A++)f(S[A],M,A)===!0&&(E=!0);return E}return f(S,_,b)}function f(y,w,p){if(w[p]===void 0)return typeof y=="number"||typeof y=="boolean"?w[p]=y:ArrayBuffer.isView(y)?w[p]=y.slice():w[p]=y.clone(),!0;{let _=w[p];if(typeof y=="number"||typeof y=="boolean"){if(_!==y)return w[p]=y,!0}else{if(ArrayBuffer.isView(y))return!0;if(_.equals(y)===!1)return _.copy(y),!0}}return!1}function x(y){let w=y.uniforms,p=0,_=16;for(let b=0,M=w.length;b<M;b++){let E=Array.isArray(w[b])?w[b]:[w[b]];for(let A=0,I=E.length;A<I;A++){let N=E[A],L=Array.isArray(N.value)?N.value:[N.value],P=Array.isArray(w[b])||Array.isArray(N.value),U=p;for(let O=0,Q=L.length;O<Q;O++){let G=L[O],Z=v(G,P),et=p%_,ht=et%Z.boundary,Pt=et+ht;p+=ht,Pt!==0&&_-Pt<Z.storage&&(p+=_-Pt),O===0&&(U=p),p+=Z.storage}let V=N.type==="int"?Int32Array:N.type==="uint"?Uint32Array:Float32Array;N.__data=new V((p-U)/Float32Array.BYTES_PER_ELEMENT),N.__offset=U}}let S=p%_;return S>0&&(p+=_-S),y.__size=p,y.__cache={},this}function v(y,w){let p={boundary:0,storage:0};return typeof y=="number"||typeof y=="boolean"?(p.boundary=4,p.storage=4):y.isVector2?(p.boundary=8,p.storage=8):y.isVector3||y.isColor?(p.boundary=16,p.storage=12):y.isVector4?(p.boundary=16,p.storage=16):y.isMatrix3?(p.boundary=16,p.storage=48):y.isMatrix4?(p.boundary=16,p.storage=64):y.isTexture?Ft("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(y)?(p.boundary=16,p.storage=y.byteLength):Ft("WebGLRenderer: Unsupported uniform value type.",y),w===!0&&(p.boundary=16,p.storage=Math.ceil(p.storage/16)*16),p}function m(y){let w=y.target;w.removeEventListener("dispose",m),i.deleteBuffer(a[w.id]),delete a[w.id],delete s[w.id]}function g(){for(let y in a)i.deleteBuffer(a[y]);a={},s={}}return{bind:r,update:o,dispose:g}}function hv(){return di===null&&(di=new Ei(lv,16,16,hi,Zn),di.name="DFG_LUT",di.minFilter=mn,di.magFilter=mn,di.wrapS=si,di.wrapT=si,di.generateMipmaps=!1,di.needsUpdate=!0),di}var Tb,Ib,Rb,Cb,Nb,Pb,Lb,Db,Ub,Ob,Fb,Bb,kb,zb,Vb,Hb,Gb,Wb,jb,Xb,qb,Yb,Jb,Kb,Zb,Qb,$b,tx,ex,nx,ix,ax,sx,rx,ox,cx,lx,hx,dx,ux,fx,px,mx,gx,bx,xx,yx,_x,vx,Mx,Sx,wx,Ax,Ex,Tx,Ix,Rx,Cx,Nx,Px,Lx,Dx,Ux,Ox,Fx,Bx,kx,zx,Vx,Hx,Gx,Wx,jx,Xx,qx,Yx,Jx,Kx,Zx,Qx,$x,t0,e0,n0,i0,a0,s0,r0,o0,c0,l0,h0,d0,u0,f0,p0,m0,g0,b0,x0,y0,_0,v0,M0,S0,w0,A0,E0,T0,I0,R0,C0,N0,P0,L0,D0,U0,O0,F0,B0,k0,z0,V0,H0,G0,W0,j0,X0,q0,Y0,J0,K0,Z0,Q0,$0,ty,ey,ny,iy,ay,sy,qt,yt,xn,tl,ry,hp,Vr,Hf,uy,fy,dp,up,py,my,gy,nl,Ty,fp,pp,mp,gp,bp,xp,Xf,qf,Yf,Jf,Kf,pd,md,gd,ud,ps,g_,b_,$f,v_,el,T_,R_,N_,L_,U_,B_,xd,yd,X_,K_,Z_,Q_,$_,cp,kr,fd,av,sv,_d,vd,rv,yp,lv,di,il,gs=ha(()=>{dd();dd();Tb=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,Ib=`#ifdef USE_ALPHAHASH
	const float ALPHA_HASH_SCALE = 0.05;
	float hash2D( vec2 value ) {
		return fract( 1.0e4 * sin( 17.0 * value.x + 0.1 * value.y ) * ( 0.1 + abs( sin( 13.0 * value.y + value.x ) ) ) );
	}
	float hash3D( vec3 value ) {
		return hash2D( vec2( hash2D( value.xy ), value.z ) );
	}
	float getAlphaHashThreshold( vec3 position ) {
		float maxDeriv = max(
			length( dFdx( position.xyz ) ),
			length( dFdy( position.xyz ) )
		);
		float pixScale = 1.0 / ( ALPHA_HASH_SCALE * maxDeriv );
		vec2 pixScales = vec2(
			exp2( floor( log2( pixScale ) ) ),
			exp2( ceil( log2( pixScale ) ) )
		);
		vec2 alpha = vec2(
			hash3D( floor( pixScales.x * position.xyz ) ),
			hash3D( floor( pixScales.y * position.xyz ) )
		);
		float lerpFactor = fract( log2( pixScale ) );
		float x = ( 1.0 - lerpFactor ) * alpha.x + lerpFactor * alpha.y;
		float a = min( lerpFactor, 1.0 - lerpFactor );
		vec3 cases = vec3(
			x * x / ( 2.0 * a * ( 1.0 - a ) ),
			( x - 0.5 * a ) / ( 1.0 - a ),
			1.0 - ( ( 1.0 - x ) * ( 1.0 - x ) / ( 2.0 * a * ( 1.0 - a ) ) )
		);
		float threshold = ( x < ( 1.0 - a ) )
			? ( ( x < a ) ? cases.x : cases.y )
			: cases.z;
		return clamp( threshold , 1.0e-6, 1.0 );
	}
#endif`,Rb=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,Cb=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,Nb=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,Pb=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,Lb=`#ifdef USE_AOMAP
	float ambientOcclusion = ( texture2D( aoMap, vAoMapUv ).r - 1.0 ) * aoMapIntensity + 1.0;
	reflectedLight.indirectDiffuse *= ambientOcclusion;
	#if defined( USE_CLEARCOAT ) 
		clearcoatSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_SHEEN ) 
		sheenSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD )
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		reflectedLight.indirectSpecular *= computeSpecularOcclusion( dotNV, ambientOcclusion, material.roughness );
	#endif
#endif`,Db=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,Ub=`#ifdef USE_BATCHING
	#if ! defined( GL_ANGLE_multi_draw )
	#define gl_DrawID _gl_DrawID
	uniform int _gl_DrawID;
	#endif
	uniform highp sampler2D batchingTexture;
	uniform highp usampler2D batchingIdTexture;
	mat4 getBatchingMatrix( const in float i ) {
		int size = textureSize( batchingTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( batchingTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( batchingTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( batchingTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( batchingTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
	float getIndirectIndex( const in int i ) {
		int size = textureSize( batchingIdTexture, 0 ).x;
		int x = i % size;
		int y = i / size;
		return float( texelFetch( batchingIdTexture, ivec2( x, y ), 0 ).r );
	}
#endif
#ifdef USE_BATCHING_COLOR
	uniform sampler2D batchingColorTexture;
	vec4 getBatchingColor( const in float i ) {
		int size = textureSize( batchingColorTexture, 0 ).x;
		int j = int( i );
		int x = j % size;
		int y = j / size;
		return texelFetch( batchingColorTexture, ivec2( x, y ), 0 );
	}
#endif`,Ob=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,Fb=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,Bb=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,kb=`float G_BlinnPhong_Implicit( ) {
	return 0.25;
}
float D_BlinnPhong( const in float shininess, const in float dotNH ) {
	return RECIPROCAL_PI * ( shininess * 0.5 + 1.0 ) * pow( dotNH, shininess );
}
vec3 BRDF_BlinnPhong( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 specularColor, const in float shininess ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( specularColor, 1.0, dotVH );
	float G = G_BlinnPhong_Implicit( );
	float D = D_BlinnPhong( shininess, dotNH );
	return F * ( G * D );
} // validated`,zb=`#ifdef USE_IRIDESCENCE
	const mat3 XYZ_TO_REC709 = mat3(
		 3.2404542, -0.9692660,  0.0556434,
		-1.5371385,  1.8760108, -0.2040259,
		-0.4985314,  0.0415560,  1.0572252
	);
	vec3 Fresnel0ToIor( vec3 fresnel0 ) {
		vec3 sqrtF0 = sqrt( fresnel0 );
		return ( vec3( 1.0 ) + sqrtF0 ) / ( vec3( 1.0 ) - sqrtF0 );
	}
	vec3 IorToFresnel0( vec3 transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - vec3( incidentIor ) ) / ( transmittedIor + vec3( incidentIor ) ) );
	}
	float IorToFresnel0( float transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - incidentIor ) / ( transmittedIor + incidentIor ));
	}
	vec3 evalSensitivity( float OPD, vec3 shift ) {
		float phase = 2.0 * PI * OPD * 1.0e-9;
		vec3 val = vec3( 5.4856e-13, 4.4201e-13, 5.2481e-13 );
		vec3 pos = vec3( 1.6810e+06, 1.7953e+06, 2.2084e+06 );
		vec3 var = vec3( 4.3278e+09, 9.3046e+09, 6.6121e+09 );
		vec3 xyz = val * sqrt( 2.0 * PI * var ) * cos( pos * phase + shift ) * exp( - pow2( phase ) * var );
		xyz.x += 9.7470e-14 * sqrt( 2.0 * PI * 4.5282e+09 ) * cos( 2.2399e+06 * phase + shift[ 0 ] ) * exp( - 4.5282e+09 * pow2( phase ) );
		xyz /= 1.0685e-7;
		vec3 rgb = XYZ_TO_REC709 * xyz;
		return rgb;
	}
	vec3 evalIridescence( float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0 ) {
		vec3 I;
		float iridescenceIOR = mix( outsideIOR, eta2, smoothstep( 0.0, 0.03, thinFilmThickness ) );
		float sinTheta2Sq = pow2( outsideIOR / iridescenceIOR ) * ( 1.0 - pow2( cosTheta1 ) );
		float cosTheta2Sq = 1.0 - sinTheta2Sq;
		if ( cosTheta2Sq < 0.0 ) {
			return vec3( 1.0 );
		}
		float cosTheta2 = sqrt( cosTheta2Sq );
		float R0 = IorToFresnel0( iridescenceIOR, outsideIOR );
		float R12 = F_Schlick( R0, 1.0, cosTheta1 );
		float T121 = 1.0 - R12;
		float phi12 = 0.0;
		if ( iridescenceIOR < outsideIOR ) phi12 = PI;
		float phi21 = PI - phi12;
		vec3 baseIOR = Fresnel0ToIor( clamp( baseF0, 0.0, 0.9999 ) );		vec3 R1 = IorToFresnel0( baseIOR, iridescenceIOR );
		vec3 R23 = F_Schlick( R1, 1.0, cosTheta2 );
		vec3 phi23 = vec3( 0.0 );
		if ( baseIOR[ 0 ] < iridescenceIOR ) phi23[ 0 ] = PI;
		if ( baseIOR[ 1 ] < iridescenceIOR ) phi23[ 1 ] = PI;
		if ( baseIOR[ 2 ] < iridescenceIOR ) phi23[ 2 ] = PI;
		float OPD = 2.0 * iridescenceIOR * thinFilmThickness * cosTheta2;
		vec3 phi = vec3( phi21 ) + phi23;
		vec3 R123 = clamp( R12 * R23, 1e-5, 0.9999 );
		vec3 r123 = sqrt( R123 );
		vec3 Rs = pow2( T121 ) * R23 / ( vec3( 1.0 ) - R123 );
		vec3 C0 = R12 + Rs;
		I = C0;
		vec3 Cm = Rs - T121;
		for ( int m = 1; m <= 2; ++ m ) {
			Cm *= r123;
			vec3 Sm = 2.0 * evalSensitivity( float( m ) * OPD, float( m ) * phi );
			I += Cm * Sm;
		}
		return max( I, vec3( 0.0 ) );
	}
#endif`,Vb=`#ifdef USE_BUMPMAP
	uniform sampler2D bumpMap;
	uniform float bumpScale;
	vec2 dHdxy_fwd() {
		vec2 dSTdx = dFdx( vBumpMapUv );
		vec2 dSTdy = dFdy( vBumpMapUv );
		float Hll = bumpScale * texture2D( bumpMap, vBumpMapUv ).x;
		float dBx = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdx ).x - Hll;
		float dBy = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdy ).x - Hll;
		return vec2( dBx, dBy );
	}
	vec3 perturbNormalArb( vec3 surf_pos, vec3 surf_norm, vec2 dHdxy, float faceDirection ) {
		vec3 vSigmaX = normalize( dFdx( surf_pos.xyz ) );
		vec3 vSigmaY = normalize( dFdy( surf_pos.xyz ) );
		vec3 vN = surf_norm;
		vec3 R1 = cross( vSigmaY, vN );
		vec3 R2 = cross( vN, vSigmaX );
		float fDet = dot( vSigmaX, R1 ) * faceDirection;
		vec3 vGrad = sign( fDet ) * ( dHdxy.x * R1 + dHdxy.y * R2 );
		return normalize( abs( fDet ) * surf_norm - vGrad );
	}
#endif`,Hb=`#if NUM_CLIPPING_PLANES > 0
	vec4 plane;
	#ifdef ALPHA_TO_COVERAGE
		float distanceToPlane, distanceGradient;
		float clipOpacity = 1.0;
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
			distanceGradient = fwidth( distanceToPlane ) / 2.0;
			clipOpacity *= smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			if ( clipOpacity == 0.0 ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			float unionClipOpacity = 1.0;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
				distanceGradient = fwidth( distanceToPlane ) / 2.0;
				unionClipOpacity *= 1.0 - smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			}
			#pragma unroll_loop_end
			clipOpacity *= 1.0 - unionClipOpacity;
		#endif
		diffuseColor.a *= clipOpacity;
		if ( diffuseColor.a == 0.0 ) discard;
	#else
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			if ( dot( vClipPosition, plane.xyz ) > plane.w ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			bool clipped = true;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				clipped = ( dot( vClipPosition, plane.xyz ) > plane.w ) && clipped;
			}
			#pragma unroll_loop_end
			if ( clipped ) discard;
		#endif
	#endif
#endif`,Gb=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,Wb=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,jb=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,Xb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,qb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,Yb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,Jb=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	vColor = vec4( 1.0 );
#endif
#ifdef USE_COLOR_ALPHA
	vColor *= color;
#elif defined( USE_COLOR )
	vColor.rgb *= color;
#endif
#ifdef USE_INSTANCING_COLOR
	vColor.rgb *= instanceColor.rgb;
#endif
#ifdef USE_BATCHING_COLOR
	vColor *= getBatchingColor( getIndirectIndex( gl_DrawID ) );
#endif`,Kb=`#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
#define whiteComplement( a ) ( 1.0 - saturate( a ) )
float pow2( const in float x ) { return x*x; }
vec3 pow2( const in vec3 x ) { return x*x; }
float pow3( const in float x ) { return x*x*x; }
float pow4( const in float x ) { float x2 = x*x; return x2*x2; }
float max3( const in vec3 v ) { return max( max( v.x, v.y ), v.z ); }
float average( const in vec3 v ) { return dot( v, vec3( 0.3333333 ) ); }
highp float rand( const in vec2 uv ) {
	const highp float a = 12.9898, b = 78.233, c = 43758.5453;
	highp float dt = dot( uv.xy, vec2( a,b ) ), sn = mod( dt, PI );
	return fract( sin( sn ) * c );
}
#ifdef HIGH_PRECISION
	float precisionSafeLength( vec3 v ) { return length( v ); }
#else
	float precisionSafeLength( vec3 v ) {
		float maxComponent = max3( abs( v ) );
		return length( v / maxComponent ) * maxComponent;
	}
#endif
struct IncidentLight {
	vec3 color;
	vec3 direction;
	bool visible;
};
struct ReflectedLight {
	vec3 directDiffuse;
	vec3 directSpecular;
	vec3 indirectDiffuse;
	vec3 indirectSpecular;
};
#ifdef USE_ALPHAHASH
	varying vec3 vPosition;
#endif
vec3 transformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );
}
#define inverseTransformDirection transformDirectionByInverseViewMatrix
vec3 transformNormalByInverseViewMatrix( in vec3 normal, in mat4 viewMatrix ) {
	return normalize( ( vec4( normal, 0.0 ) * viewMatrix ).xyz );
}
vec3 transformDirectionByInverseViewMatrix( in vec3 dir, in mat4 viewMatrix ) {
	return normalize( ( vec4( dir, 0.0 ) * viewMatrix ).xyz );
}
bool isPerspectiveMatrix( mat4 m ) {
	return m[ 2 ][ 3 ] == - 1.0;
}
vec2 equirectUv( in vec3 dir ) {
	float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;
	float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;
	return vec2( u, v );
}
vec3 BRDF_Lambert( const in vec3 diffuseColor ) {
	return RECIPROCAL_PI * diffuseColor;
}
vec3 F_Schlick( const in vec3 f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
}
float F_Schlick( const in float f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
} // validated`,Zb=`vec3 transformedNormal = objectNormal;
#ifdef USE_TANGENT
	vec3 transformedTangent = objectTangent;
#endif
#ifdef USE_BATCHING
	mat3 bm = mat3( batchingMatrix );
	transformedNormal /= vec3( dot( bm[ 0 ], bm[ 0 ] ), dot( bm[ 1 ], bm[ 1 ] ), dot( bm[ 2 ], bm[ 2 ] ) );
	transformedNormal = bm * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = bm * transformedTangent;
	#endif
#endif
#ifdef USE_INSTANCING
	mat3 im = mat3( instanceMatrix );
	transformedNormal /= vec3( dot( im[ 0 ], im[ 0 ] ), dot( im[ 1 ], im[ 1 ] ), dot( im[ 2 ], im[ 2 ] ) );
	transformedNormal = im * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = im * transformedTangent;
	#endif
#endif
transformedNormal = normalMatrix * transformedNormal;
#ifdef FLIP_SIDED
	transformedNormal = - transformedNormal;
#endif
#ifdef USE_TANGENT
	transformedTangent = ( modelViewMatrix * vec4( transformedTangent, 0.0 ) ).xyz;
#endif`,Qb=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,$b=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,tx=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,ex=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,nx="gl_FragColor = linearToOutputTexel( gl_FragColor );",ix=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,ax=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vec3 cameraToFrag;
		if ( isOrthographic ) {
			cameraToFrag = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToFrag = normalize( vWorldPosition - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vec3 reflectVec = reflect( cameraToFrag, worldNormal );
		#else
			vec3 reflectVec = refract( cameraToFrag, worldNormal, refractionRatio );
		#endif
	#else
		vec3 reflectVec = vReflect;
	#endif
	#ifdef ENVMAP_TYPE_CUBE
		vec4 envColor = textureCube( envMap, envMapRotation * reflectVec );
		#ifdef ENVMAP_BLENDING_MULTIPLY
			outgoingLight = mix( outgoingLight, outgoingLight * envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_MIX )
			outgoingLight = mix( outgoingLight, envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_ADD )
			outgoingLight += envColor.xyz * specularStrength * reflectivity;
		#endif
	#endif
#endif`,sx=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,rx=`#ifdef USE_ENVMAP
	uniform float reflectivity;
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		varying vec3 vWorldPosition;
		uniform float refractionRatio;
	#else
		varying vec3 vReflect;
	#endif
#endif`,ox=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,cx=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vWorldPosition = worldPosition.xyz;
	#else
		vec3 cameraToVertex;
		if ( isOrthographic ) {
			cameraToVertex = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToVertex = normalize( worldPosition.xyz - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vReflect = reflect( cameraToVertex, worldNormal );
		#else
			vReflect = refract( cameraToVertex, worldNormal, refractionRatio );
		#endif
	#endif
#endif`,lx=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,hx=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,dx=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,ux=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,fx=`#ifdef USE_GRADIENTMAP
	uniform sampler2D gradientMap;
#endif
vec3 getGradientIrradiance( vec3 normal, vec3 lightDirection ) {
	float dotNL = dot( normal, lightDirection );
	vec2 coord = vec2( dotNL * 0.5 + 0.5, 0.0 );
	#ifdef USE_GRADIENTMAP
		return vec3( texture2D( gradientMap, coord ).r );
	#else
		vec2 fw = fwidth( coord ) * 0.5;
		return mix( vec3( 0.7 ), vec3( 1.0 ), smoothstep( 0.7 - fw.x, 0.7 + fw.x, coord.x ) );
	#endif
}`,px=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,mx=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,gx=`varying vec3 vViewPosition;
struct LambertMaterial {
	vec3 diffuseColor;
	float specularStrength;
};
void RE_Direct_Lambert( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Lambert( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Lambert
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,bx=`uniform bool receiveShadow;
uniform vec3 ambientLightColor;
#if defined( USE_LIGHT_PROBES )
	uniform vec3 lightProbe[ 9 ];
#endif
vec3 shGetIrradianceAt( in vec3 normal, in vec3 shCoefficients[ 9 ] ) {
	float x = normal.x, y = normal.y, z = normal.z;
	vec3 result = shCoefficients[ 0 ] * 0.886227;
	result += shCoefficients[ 1 ] * 2.0 * 0.511664 * y;
	result += shCoefficients[ 2 ] * 2.0 * 0.511664 * z;
	result += shCoefficients[ 3 ] * 2.0 * 0.511664 * x;
	result += shCoefficients[ 4 ] * 2.0 * 0.429043 * x * y;
	result += shCoefficients[ 5 ] * 2.0 * 0.429043 * y * z;
	result += shCoefficients[ 6 ] * ( 0.743125 * z * z - 0.247708 );
	result += shCoefficients[ 7 ] * 2.0 * 0.429043 * x * z;
	result += shCoefficients[ 8 ] * 0.429043 * ( x * x - y * y );
	return result;
}
vec3 getLightProbeIrradiance( const in vec3 lightProbe[ 9 ], const in vec3 normal ) {
	vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec3 irradiance = shGetIrradianceAt( worldNormal, lightProbe );
	return irradiance;
}
vec3 getAmbientLightIrradiance( const in vec3 ambientLightColor ) {
	vec3 irradiance = ambientLightColor;
	return irradiance;
}
float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	float distanceFalloff = 1.0 / max( pow( lightDistance, decayExponent ), 0.01 );
	if ( cutoffDistance > 0.0 ) {
		distanceFalloff *= pow2( saturate( 1.0 - pow4( lightDistance / cutoffDistance ) ) );
	}
	return distanceFalloff;
}
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
	return smoothstep( coneCosine, penumbraCosine, angleCosine );
}
#if NUM_SUN_LIGHTS > 0
	struct SunLight {
		vec3 direction;
		vec3 color;
	};
	uniform SunLight sunLights[ NUM_SUN_LIGHTS ];
	void getSunLightInfo( const in SunLight sunLight, out IncidentLight light ) {
		light.color = sunLight.color;
		light.direction = sunLight.direction;
		light.visible = true;
	}
#endif
#if NUM_DIR_LIGHTS > 0
	struct DirectionalLight {
		vec3 direction;
		vec3 color;
	};
	uniform DirectionalLight directionalLights[ NUM_DIR_LIGHTS ];
	void getDirectionalLightInfo( const in DirectionalLight directionalLight, out IncidentLight light ) {
		light.color = directionalLight.color;
		light.direction = directionalLight.direction;
		light.visible = true;
	}
#endif
#if NUM_POINT_LIGHTS > 0
	struct PointLight {
		vec3 position;
		vec3 color;
		float distance;
		float decay;
	};
	uniform PointLight pointLights[ NUM_POINT_LIGHTS ];
	void getPointLightInfo( const in PointLight pointLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = pointLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float lightDistance = length( lVector );
		light.color = pointLight.color;
		light.color *= getDistanceAttenuation( lightDistance, pointLight.distance, pointLight.decay );
		light.visible = ( light.color != vec3( 0.0 ) );
	}
#endif
#if NUM_SPOT_LIGHTS > 0
	struct SpotLight {
		vec3 position;
		vec3 direction;
		vec3 color;
		float distance;
		float decay;
		float coneCos;
		float penumbraCos;
	};
	uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];
	void getSpotLightInfo( const in SpotLight spotLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = spotLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float angleCos = dot( light.direction, spotLight.direction );
		float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
		if ( spotAttenuation > 0.0 ) {
			float lightDistance = length( lVector );
			light.color = spotLight.color * spotAttenuation;
			light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
			light.visible = ( light.color != vec3( 0.0 ) );
		} else {
			light.color = vec3( 0.0 );
			light.visible = false;
		}
	}
#endif
#if NUM_RECT_AREA_LIGHTS > 0
	struct RectAreaLight {
		vec3 color;
		vec3 position;
		vec3 halfWidth;
		vec3 halfHeight;
	};
	uniform sampler2D ltc_1;	uniform sampler2D ltc_2;
	uniform RectAreaLight rectAreaLights[ NUM_RECT_AREA_LIGHTS ];
#endif
#if NUM_HEMI_LIGHTS > 0
	struct HemisphereLight {
		vec3 direction;
		vec3 skyColor;
		vec3 groundColor;
	};
	uniform HemisphereLight hemisphereLights[ NUM_HEMI_LIGHTS ];
	vec3 getHemisphereLightIrradiance( const in HemisphereLight hemiLight, const in vec3 normal ) {
		float dotNL = dot( normal, hemiLight.direction );
		float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
		vec3 irradiance = mix( hemiLight.groundColor, hemiLight.skyColor, hemiDiffuseWeight );
		return irradiance;
	}
#endif
#include <lightprobes_pars_fragment>`,xx=`#ifdef USE_ENVMAP
	vec3 getIBLIrradiance( const in vec3 normal ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * worldNormal, ENVMAP_MAX_LOD );
			return PI * envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	vec3 getIBLRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 reflectVec = reflect( - viewDir, normal );
			reflectVec = normalize( mix( reflectVec, normal, pow4( roughness ) ) );
			reflectVec = transformDirectionByInverseViewMatrix( reflectVec, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * reflectVec, roughnessToMip( roughness ) );
			return envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	#ifdef USE_RETROREFLECTION
		vec3 getIBLRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 retroVec = normalize( mix( viewDir, normal, pow4( roughness ) ) );
				retroVec = transformDirectionByInverseViewMatrix( retroVec, viewMatrix );
				vec4 envMapColor = textureLod( envMap, envMapRotation * retroVec, roughnessToMip( roughness ) );
				return envMapColor.rgb * envMapIntensity;
			#else
				return vec3( 0.0 );
			#endif
		}
	#endif
	#ifdef USE_ANISOTROPY
		vec3 getIBLAnisotropyRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 bentNormal = cross( bitangent, viewDir );
				bentNormal = normalize( cross( bentNormal, bitangent ) );
				bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
				return getIBLRadiance( viewDir, bentNormal, roughness );
			#else
				return vec3( 0.0 );
			#endif
		}
		#ifdef USE_RETROREFLECTION
			vec3 getIBLAnisotropyRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
				#ifdef ENVMAP_TYPE_PMREM
					vec3 bentNormal = cross( bitangent, viewDir );
					bentNormal = normalize( cross( bentNormal, bitangent ) );
					bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
					return getIBLRetroRadiance( viewDir, bentNormal, roughness );
				#else
					return vec3( 0.0 );
				#endif
			}
		#endif
	#endif
#endif`,yx=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,_x=`varying vec3 vViewPosition;
struct ToonMaterial {
	vec3 diffuseColor;
};
void RE_Direct_Toon( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 irradiance = getGradientIrradiance( geometryNormal, directLight.direction ) * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Toon( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Toon
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,vx=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,Mx=`varying vec3 vViewPosition;
struct BlinnPhongMaterial {
	vec3 diffuseColor;
	vec3 specularColor;
	float specularShininess;
	float specularStrength;
};
void RE_Direct_BlinnPhong( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
	reflectedLight.directSpecular += irradiance * BRDF_BlinnPhong( directLight.direction, geometryViewDir, geometryNormal, material.specularColor, material.specularShininess ) * material.specularStrength;
}
void RE_IndirectDiffuse_BlinnPhong( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_BlinnPhong
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,Sx=`PhysicalMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.diffuseContribution = diffuseColor.rgb * ( 1.0 - metalnessFactor );
material.metalness = metalnessFactor;
vec3 dxy = max( abs( dFdx( nonPerturbedNormal ) ), abs( dFdy( nonPerturbedNormal ) ) );
float geometryRoughness = max( max( dxy.x, dxy.y ), dxy.z );
material.roughness = max( roughnessFactor, 0.045 );
material.roughness += geometryRoughness;
material.roughness = min( material.roughness, 1.0 );
#ifdef USE_DIFFUSE_ROUGHNESS
	float diffuseRoughnessFactor = diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		diffuseRoughnessFactor *= texture2D( diffuseRoughnessMap, vDiffuseRoughnessMapUv ).r;
	#endif
	material.diffuseRoughness = saturate( diffuseRoughnessFactor );
#endif
#ifdef IOR
	material.ior = ior;
	#ifdef USE_SPECULAR
		float specularIntensityFactor = specularIntensity;
		vec3 specularColorFactor = specularColor;
		#ifdef USE_SPECULAR_COLORMAP
			specularColorFactor *= texture2D( specularColorMap, vSpecularColorMapUv ).rgb;
		#endif
		#ifdef USE_SPECULAR_INTENSITYMAP
			specularIntensityFactor *= texture2D( specularIntensityMap, vSpecularIntensityMapUv ).a;
		#endif
		material.specularF90 = mix( specularIntensityFactor, 1.0, metalnessFactor );
	#else
		float specularIntensityFactor = 1.0;
		vec3 specularColorFactor = vec3( 1.0 );
		material.specularF90 = 1.0;
	#endif
	material.specularColor = min( pow2( ( material.ior - 1.0 ) / ( material.ior + 1.0 ) ) * specularColorFactor, vec3( 1.0 ) ) * specularIntensityFactor;
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
#else
	material.specularColor = vec3( 0.04 );
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
	material.specularF90 = 1.0;
#endif
#ifdef USE_CLEARCOAT
	material.clearcoat = clearcoat;
	material.clearcoatRoughness = clearcoatRoughness;
	material.clearcoatF0 = vec3( 0.04 );
	material.clearcoatF90 = 1.0;
	#ifdef USE_CLEARCOATMAP
		material.clearcoat *= texture2D( clearcoatMap, vClearcoatMapUv ).x;
	#endif
	#ifdef USE_CLEARCOAT_ROUGHNESSMAP
		material.clearcoatRoughness *= texture2D( clearcoatRoughnessMap, vClearcoatRoughnessMapUv ).y;
	#endif
	material.clearcoat = saturate( material.clearcoat );	material.clearcoatRoughness = max( material.clearcoatRoughness, 0.045 );
	material.clearcoatRoughness += geometryRoughness;
	material.clearcoatRoughness = min( material.clearcoatRoughness, 1.0 );
#endif
#ifdef USE_DISPERSION
	material.dispersion = dispersion;
#endif
#ifdef USE_RETROREFLECTION
	material.retroreflectivity = retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	material.iridescence = iridescence;
	material.iridescenceIOR = iridescenceIOR;
	#ifdef USE_IRIDESCENCEMAP
		material.iridescence *= texture2D( iridescenceMap, vIridescenceMapUv ).r;
	#endif
	#ifdef USE_IRIDESCENCE_THICKNESSMAP
		material.iridescenceThickness = (iridescenceThicknessMaximum - iridescenceThicknessMinimum) * texture2D( iridescenceThicknessMap, vIridescenceThicknessMapUv ).g + iridescenceThicknessMinimum;
	#else
		material.iridescenceThickness = iridescenceThicknessMaximum;
	#endif
#endif
#ifdef USE_SHEEN
	material.sheenColor = sheenColor;
	#ifdef USE_SHEEN_COLORMAP
		material.sheenColor *= texture2D( sheenColorMap, vSheenColorMapUv ).rgb;
	#endif
	material.sheenRoughness = clamp( sheenRoughness, 0.0001, 1.0 );
	#ifdef USE_SHEEN_ROUGHNESSMAP
		material.sheenRoughness *= texture2D( sheenRoughnessMap, vSheenRoughnessMapUv ).a;
	#endif
#endif
#ifdef USE_ANISOTROPY
	#ifdef USE_ANISOTROPYMAP
		mat2 anisotropyMat = mat2( anisotropyVector.x, anisotropyVector.y, - anisotropyVector.y, anisotropyVector.x );
		vec3 anisotropyPolar = texture2D( anisotropyMap, vAnisotropyMapUv ).rgb;
		vec2 anisotropyV = anisotropyMat * normalize( 2.0 * anisotropyPolar.rg - vec2( 1.0 ) ) * anisotropyPolar.b;
	#else
		vec2 anisotropyV = anisotropyVector;
	#endif
	material.anisotropy = length( anisotropyV );
	if( material.anisotropy == 0.0 ) {
		anisotropyV = vec2( 1.0, 0.0 );
	} else {
		anisotropyV /= material.anisotropy;
		material.anisotropy = saturate( material.anisotropy );
	}
	material.alphaT = mix( pow2( material.roughness ), 1.0, pow2( material.anisotropy ) );
	material.anisotropyT = tbn[ 0 ] * anisotropyV.x + tbn[ 1 ] * anisotropyV.y;
	material.anisotropyB = tbn[ 1 ] * anisotropyV.x - tbn[ 0 ] * anisotropyV.y;
#endif`,wx=`uniform sampler2D dfgLUT;
struct PhysicalMaterial {
	vec3 diffuseColor;
	vec3 diffuseContribution;
	vec3 specularColor;
	vec3 specularColorBlended;
	float roughness;
	float metalness;
	float specularF90;
	float dispersion;
	vec2 dfg;
	vec3 multiScatteringCompensation;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float diffuseRoughness;
	#endif
	#ifdef USE_RETROREFLECTION
		float retroreflectivity;
	#endif
	#ifdef USE_CLEARCOAT
		float clearcoat;
		float clearcoatRoughness;
		vec3 clearcoatF0;
		float clearcoatF90;
	#endif
	#ifdef USE_IRIDESCENCE
		float iridescence;
		float iridescenceIOR;
		float iridescenceThickness;
		vec3 iridescenceFresnel;
		vec3 iridescenceF0Dielectric;
		vec3 iridescenceF0Metallic;
	#endif
	#ifdef USE_SHEEN
		vec3 sheenColor;
		float sheenRoughness;
	#endif
	#ifdef IOR
		float ior;
	#endif
	#ifdef USE_TRANSMISSION
		float transmission;
		float transmissionAlpha;
		float thickness;
		float attenuationDistance;
		vec3 attenuationColor;
	#endif
	#ifdef USE_ANISOTROPY
		float anisotropy;
		float alphaT;
		vec3 anisotropyT;
		vec3 anisotropyB;
	#endif
};
vec3 clearcoatSpecularDirect = vec3( 0.0 );
vec3 clearcoatSpecularIndirect = vec3( 0.0 );
vec3 sheenSpecularDirect = vec3( 0.0 );
vec3 sheenSpecularIndirect = vec3(0.0 );
vec3 Schlick_to_F0( const in vec3 f, const in float f90, const in float dotVH ) {
    float x = clamp( 1.0 - dotVH, 0.0, 1.0 );
    float x2 = x * x;
    float x5 = clamp( x * x2 * x2, 0.0, 0.9999 );
    return ( f - vec3( f90 ) * x5 ) / ( 1.0 - x5 );
}
#ifdef USE_DIFFUSE_ROUGHNESS
	const float EON_EPSILON = 1e-7;
	float FON_DirectionalAlbedo( const in float mu, const in float roughness, const in float A ) {
		float muComp = 1.0 - mu;
		float gOverPi = muComp * ( 0.0571085289 + muComp * ( 0.491881867 + muComp * ( - 0.332181442 + muComp * 0.0714429953 ) ) );
		return A * ( 1.0 + roughness * gOverPi );
	}
	vec3 BRDF_EON( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 diffuseColor, const in float roughness ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return BRDF_Lambert( rho );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float s = dot( lightDir, viewDir ) - dotNL * dotNV;
		float sOverT = ( s > 0.0 ) ? s / max( max( dotNL, dotNV ), EON_EPSILON ) : s;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		vec3 singleScatter = rho * RECIPROCAL_PI * A * ( 1.0 + roughness * sOverT );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		float albedoV = FON_DirectionalAlbedo( dotNV, roughness, A );
		float albedoL = FON_DirectionalAlbedo( dotNL, roughness, A );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		vec3 multiScatter = rhoMultiScatter * RECIPROCAL_PI
			* max( EON_EPSILON, 1.0 - albedoV )
			* max( EON_EPSILON, 1.0 - albedoL )
			/ max( EON_EPSILON, 1.0 - averageAlbedo );
		return singleScatter + multiScatter;
	}
	vec3 EON_DirectionalAlbedo( const in vec3 diffuseColor, const in float roughness, const in float dotNV ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return rho;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		float directionalAlbedo = FON_DirectionalAlbedo( dotNV, roughness, A );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		return rho * directionalAlbedo + rhoMultiScatter * ( 1.0 - directionalAlbedo );
	}
#endif
float V_GGX_SmithCorrelated( const in float alpha, const in float dotNL, const in float dotNV ) {
	float a2 = pow2( alpha );
	float gv = dotNL * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNV ) );
	float gl = dotNV * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNL ) );
	return 0.5 / max( gv + gl, EPSILON );
}
float D_GGX( const in float alpha, const in float dotNH ) {
	float a2 = pow2( alpha );
	float denom = pow2( dotNH ) * ( a2 - 1.0 ) + 1.0;
	return RECIPROCAL_PI * a2 / pow2( denom );
}
#ifdef USE_ANISOTROPY
	float V_GGX_SmithCorrelated_Anisotropic( const in float alphaT, const in float alphaB, const in float dotTV, const in float dotBV, const in float dotTL, const in float dotBL, const in float dotNV, const in float dotNL ) {
		float gv = dotNL * length( vec3( alphaT * dotTV, alphaB * dotBV, dotNV ) );
		float gl = dotNV * length( vec3( alphaT * dotTL, alphaB * dotBL, dotNL ) );
		return 0.5 / max( gv + gl, EPSILON );
	}
	float D_GGX_Anisotropic( const in float alphaT, const in float alphaB, const in float dotNH, const in float dotTH, const in float dotBH ) {
		float a2 = alphaT * alphaB;
		highp vec3 v = vec3( alphaB * dotTH, alphaT * dotBH, a2 * dotNH );
		highp float v2 = dot( v, v );
		float w2 = a2 / v2;
		return RECIPROCAL_PI * a2 * pow2 ( w2 );
	}
#endif
#ifdef USE_CLEARCOAT
	vec3 BRDF_GGX_Clearcoat( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material) {
		vec3 f0 = material.clearcoatF0;
		float f90 = material.clearcoatF90;
		float roughness = max( material.clearcoatRoughness, 0.045 );
		float alpha = pow2( roughness );
		vec3 halfDir = normalize( lightDir + viewDir );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float dotNH = saturate( dot( normal, halfDir ) );
		float dotVH = saturate( dot( viewDir, halfDir ) );
		vec3 F = F_Schlick( f0, f90, dotVH );
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
		return F * ( V * D );
	}
#endif
vec3 BRDF_GGX( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material ) {
	vec3 f0 = material.specularColorBlended;
	float f90 = material.specularF90;
	float roughness = max( material.roughness, 0.045 );
	float alpha = pow2( roughness );
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( f0, f90, dotVH );
	#ifdef USE_IRIDESCENCE
		F = mix( F, material.iridescenceFresnel, material.iridescence );
	#endif
	#ifdef USE_ANISOTROPY
		float dotTL = dot( material.anisotropyT, lightDir );
		float dotTV = dot( material.anisotropyT, viewDir );
		float dotTH = dot( material.anisotropyT, halfDir );
		float dotBL = dot( material.anisotropyB, lightDir );
		float dotBV = dot( material.anisotropyB, viewDir );
		float dotBH = dot( material.anisotropyB, halfDir );
		float alphaT = max( material.alphaT, alpha );
		float V = V_GGX_SmithCorrelated_Anisotropic( alphaT, alpha, dotTV, dotBV, dotTL, dotBL, dotNV, dotNL );
		float D = D_GGX_Anisotropic( alphaT, alpha, dotNH, dotTH, dotBH );
	#else
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
	#endif
	return F * ( V * D );
}
vec2 LTC_Uv( const in vec3 N, const in vec3 V, const in float roughness ) {
	const float LUT_SIZE = 64.0;
	const float LUT_SCALE = ( LUT_SIZE - 1.0 ) / LUT_SIZE;
	const float LUT_BIAS = 0.5 / LUT_SIZE;
	float dotNV = saturate( dot( N, V ) );
	vec2 uv = vec2( roughness, sqrt( 1.0 - dotNV ) );
	uv = uv * LUT_SCALE + LUT_BIAS;
	return uv;
}
float LTC_ClippedSphereFormFactor( const in vec3 f ) {
	float l = length( f );
	return max( ( l * l + f.z ) / ( l + 1.0 ), 0.0 );
}
vec3 LTC_EdgeVectorFormFactor( const in vec3 v1, const in vec3 v2 ) {
	float x = dot( v1, v2 );
	float y = abs( x );
	float a = 0.8543985 + ( 0.4965155 + 0.0145206 * y ) * y;
	float b = 3.4175940 + ( 4.1616724 + y ) * y;
	float v = a / b;
	float theta_sintheta = ( x > 0.0 ) ? v : 0.5 * inversesqrt( max( 1.0 - x * x, 1e-7 ) ) - v;
	return cross( v1, v2 ) * theta_sintheta;
}
vec3 LTC_Evaluate( const in vec3 N, const in vec3 V, const in vec3 P, const in mat3 mInv, const in vec3 rectCoords[ 4 ] ) {
	vec3 v1 = rectCoords[ 1 ] - rectCoords[ 0 ];
	vec3 v2 = rectCoords[ 3 ] - rectCoords[ 0 ];
	vec3 lightNormal = cross( v1, v2 );
	if( dot( lightNormal, P - rectCoords[ 0 ] ) < 0.0 ) return vec3( 0.0 );
	vec3 T1, T2;
	T1 = normalize( V - N * dot( V, N ) );
	T2 = - cross( N, T1 );
	mat3 mat = mInv * transpose( mat3( T1, T2, N ) );
	vec3 coords[ 4 ];
	coords[ 0 ] = mat * ( rectCoords[ 0 ] - P );
	coords[ 1 ] = mat * ( rectCoords[ 1 ] - P );
	coords[ 2 ] = mat * ( rectCoords[ 2 ] - P );
	coords[ 3 ] = mat * ( rectCoords[ 3 ] - P );
	coords[ 0 ] = normalize( coords[ 0 ] );
	coords[ 1 ] = normalize( coords[ 1 ] );
	coords[ 2 ] = normalize( coords[ 2 ] );
	coords[ 3 ] = normalize( coords[ 3 ] );
	vec3 vectorFormFactor = vec3( 0.0 );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 0 ], coords[ 1 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 1 ], coords[ 2 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 2 ], coords[ 3 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 3 ], coords[ 0 ] );
	float result = LTC_ClippedSphereFormFactor( vectorFormFactor );
	return vec3( result );
}
#if defined( USE_SHEEN )
float D_Charlie( float roughness, float dotNH ) {
	float alpha = pow2( roughness );
	float invAlpha = 1.0 / alpha;
	float cos2h = dotNH * dotNH;
	float sin2h = max( 1.0 - cos2h, 0.0078125 );
	return ( 2.0 + invAlpha ) * pow( sin2h, invAlpha * 0.5 ) / ( 2.0 * PI );
}
float V_Neubelt( float dotNV, float dotNL ) {
	return saturate( 1.0 / ( 4.0 * ( dotNL + dotNV - dotNL * dotNV ) ) );
}
vec3 BRDF_Sheen( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, vec3 sheenColor, const in float sheenRoughness ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float D = D_Charlie( sheenRoughness, dotNH );
	float V = V_Neubelt( dotNV, dotNL );
	return sheenColor * ( D * V );
}
#endif
float IBLSheenBRDF( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	float r2 = roughness * roughness;
	float rInv = 1.0 / ( roughness + 0.1 );
	float a = -1.9362 + 1.0678 * roughness + 0.4573 * r2 - 0.8469 * rInv;
	float b = -0.6014 + 0.5538 * roughness - 0.4670 * r2 - 0.1255 * rInv;
	float DG = exp( a * dotNV + b );
	return saturate( DG );
}
vec3 EnvironmentBRDF( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	vec2 fab = texture2D( dfgLUT, vec2( roughness, dotNV ) ).rg;
	return specularColor * fab.x + specularF90 * fab.y;
}
#ifdef USE_IRIDESCENCE
void computeMultiscatteringIridescence( const in vec2 fab, const in vec3 specularColor, const in float specularF90, const in float iridescence, const in vec3 iridescenceF0, inout vec3 singleScatter, inout vec3 multiScatter ) {
#else
void computeMultiscattering( const in vec2 fab, const in vec3 specularColor, const in float specularF90, inout vec3 singleScatter, inout vec3 multiScatter ) {
#endif
	#ifdef USE_IRIDESCENCE
		vec3 Fr = mix( specularColor, iridescenceF0, iridescence );
	#else
		vec3 Fr = specularColor;
	#endif
	vec3 FssEss = Fr * fab.x + specularF90 * fab.y;
	float Ess = fab.x + fab.y;
	float Ems = 1.0 - Ess;
	vec3 Favg = Fr + ( 1.0 - Fr ) * 0.047619;	vec3 Fms = FssEss * Favg / ( 1.0 - Ems * Favg );
	singleScatter += FssEss;
	multiScatter += Fms * Ems;
}
#if NUM_RECT_AREA_LIGHTS > 0
	void RE_Direct_RectArea_Physical( const in RectAreaLight rectAreaLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
		vec3 normal = geometryNormal;
		vec3 viewDir = geometryViewDir;
		vec3 position = geometryPosition;
		vec3 lightPos = rectAreaLight.position;
		vec3 halfWidth = rectAreaLight.halfWidth;
		vec3 halfHeight = rectAreaLight.halfHeight;
		vec3 lightColor = rectAreaLight.color;
		float roughness = material.roughness;
		vec3 rectCoords[ 4 ];
		rectCoords[ 0 ] = lightPos + halfWidth - halfHeight;		rectCoords[ 1 ] = lightPos - halfWidth - halfHeight;
		rectCoords[ 2 ] = lightPos - halfWidth + halfHeight;
		rectCoords[ 3 ] = lightPos + halfWidth + halfHeight;
		vec2 uv = LTC_Uv( normal, viewDir, roughness );
		vec4 t1 = texture2D( ltc_1, uv );
		vec4 t2 = texture2D( ltc_2, uv );
		mat3 mInv = mat3(
			vec3( t1.x, 0, t1.y ),
			vec3(    0, 1,    0 ),
			vec3( t1.z, 0, t1.w )
		);
		vec3 fresnel = ( material.specularColorBlended * t2.x + ( material.specularF90 - material.specularColorBlended ) * t2.y );
		reflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );
		reflectedLight.directDiffuse += lightColor * material.diffuseContribution * LTC_Evaluate( normal, viewDir, position, mat3( 1.0 ), rectCoords );
		#ifdef USE_CLEARCOAT
			vec3 Ncc = geometryClearcoatNormal;
			vec2 uvClearcoat = LTC_Uv( Ncc, viewDir, material.clearcoatRoughness );
			vec4 t1Clearcoat = texture2D( ltc_1, uvClearcoat );
			vec4 t2Clearcoat = texture2D( ltc_2, uvClearcoat );
			mat3 mInvClearcoat = mat3(
				vec3( t1Clearcoat.x, 0, t1Clearcoat.y ),
				vec3(             0, 1,             0 ),
				vec3( t1Clearcoat.z, 0, t1Clearcoat.w )
			);
			vec3 fresnelClearcoat = material.clearcoatF0 * t2Clearcoat.x + ( material.clearcoatF90 - material.clearcoatF0 ) * t2Clearcoat.y;
			clearcoatSpecularDirect += lightColor * fresnelClearcoat * LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );
		#endif
	}
#endif
void RE_Direct_Physical( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	#ifdef USE_CLEARCOAT
		float dotNLcc = saturate( dot( geometryClearcoatNormal, directLight.direction ) );
		vec3 ccIrradiance = dotNLcc * directLight.color;
		clearcoatSpecularDirect += ccIrradiance * BRDF_GGX_Clearcoat( directLight.direction, geometryViewDir, geometryClearcoatNormal, material );
	#endif
	#ifdef USE_SHEEN
 
 		sheenSpecularDirect += irradiance * BRDF_Sheen( directLight.direction, geometryViewDir, geometryNormal, material.sheenColor, material.sheenRoughness );
 
 		float sheenAlbedoV = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
 		float sheenAlbedoL = IBLSheenBRDF( geometryNormal, directLight.direction, material.sheenRoughness );
 
 		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * max( sheenAlbedoV, sheenAlbedoL );
 
 		irradiance *= sheenEnergyComp;
 
 	#endif
	vec3 specularBRDF = BRDF_GGX( directLight.direction, geometryViewDir, geometryNormal, material );
	#ifdef USE_RETROREFLECTION
		vec3 retroViewDir = reflect( - geometryViewDir, geometryNormal );
		vec3 retroSpecularBRDF = BRDF_GGX( directLight.direction, retroViewDir, geometryNormal, material );
		specularBRDF = mix( specularBRDF, retroSpecularBRDF, saturate( material.retroreflectivity ) );
	#endif
	reflectedLight.directSpecular += irradiance * specularBRDF * material.multiScatteringCompensation;
	vec3 halfDir = normalize( directLight.direction + geometryViewDir );
	float dotVH = saturate( dot( geometryViewDir, halfDir ) );
	vec3 F = F_Schlick( material.specularColor, material.specularF90, dotVH );
	#ifdef USE_RETROREFLECTION
		vec3 retroHalfDir = normalize( directLight.direction + retroViewDir );
		float dotRetroVH = saturate( dot( retroViewDir, retroHalfDir ) );
		vec3 retroF = F_Schlick( material.specularColor, material.specularF90, dotRetroVH );
		F = mix( F, retroF, saturate( material.retroreflectivity ) );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		vec3 diffuseBRDF = BRDF_EON( directLight.direction, geometryViewDir, geometryNormal, material.diffuseColor, material.diffuseRoughness ) * ( 1.0 - material.metalness );
	#else
		vec3 diffuseBRDF = BRDF_Lambert( material.diffuseContribution );
	#endif
	reflectedLight.directDiffuse += irradiance * diffuseBRDF * ( 1.0 - F );
}
void RE_IndirectDiffuse_Physical( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 singleScattering = vec3( 0.0 );
	vec3 multiScattering = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScattering, multiScattering );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScattering, multiScattering );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuseAlbedo = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness );
		vec3 diffuse = irradiance * RECIPROCAL_PI * diffuseAlbedo * ( 1.0 - singleScattering - multiScattering );
	#else
		vec3 diffuse = irradiance * BRDF_Lambert( material.diffuseContribution ) * ( 1.0 - singleScattering - multiScattering );
	#endif
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		sheenSpecularIndirect += irradiance * material.sheenColor * sheenAlbedo * RECIPROCAL_PI;
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		diffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectDiffuse += diffuse;
}
void RE_IndirectSpecular_Physical( const in vec3 radiance, const in vec3 irradiance, const in vec3 clearcoatRadiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight) {
	#ifdef USE_CLEARCOAT
		clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularIndirect += irradiance * material.sheenColor * IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness ) * RECIPROCAL_PI;
 	#endif
	vec3 singleScatteringDielectric = vec3( 0.0 );
	vec3 multiScatteringDielectric = vec3( 0.0 );
	vec3 singleScatteringMetallic = vec3( 0.0 );
	vec3 multiScatteringMetallic = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscatteringIridescence( material.dfg, material.diffuseColor, material.specularF90, material.iridescence, material.iridescenceF0Metallic, singleScatteringMetallic, multiScatteringMetallic );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscattering( material.dfg, material.diffuseColor, material.specularF90, singleScatteringMetallic, multiScatteringMetallic );
	#endif
	vec3 singleScattering = mix( singleScatteringDielectric, singleScatteringMetallic, material.metalness );
	vec3 multiScattering = mix( multiScatteringDielectric, multiScatteringMetallic, material.metalness );
	vec3 totalScatteringDielectric = singleScatteringDielectric + multiScatteringDielectric;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuse = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness ) * ( 1.0 - totalScatteringDielectric );
	#else
		vec3 diffuse = material.diffuseContribution * ( 1.0 - totalScatteringDielectric );
	#endif
	vec3 cosineWeightedIrradiance = irradiance * RECIPROCAL_PI;
	vec3 indirectSpecular = radiance * singleScattering;
	indirectSpecular += multiScattering * cosineWeightedIrradiance;
	vec3 indirectDiffuse = diffuse * cosineWeightedIrradiance;
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		indirectSpecular *= sheenEnergyComp;
		indirectDiffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectSpecular += indirectSpecular;
	reflectedLight.indirectDiffuse += indirectDiffuse;
}
#define RE_Direct				RE_Direct_Physical
#define RE_Direct_RectArea		RE_Direct_RectArea_Physical
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Physical
#define RE_IndirectSpecular		RE_IndirectSpecular_Physical
float computeSpecularOcclusion( const in float dotNV, const in float ambientOcclusion, const in float roughness ) {
	return saturate( pow( dotNV + ambientOcclusion, exp2( - 16.0 * roughness - 1.0 ) ) - 1.0 + ambientOcclusion );
}`,Ax=`
vec3 geometryPosition = - vViewPosition;
vec3 geometryNormal = normal;
vec3 geometryViewDir = ( isOrthographic ) ? vec3( 0, 0, 1 ) : normalize( vViewPosition );
vec3 geometryClearcoatNormal = vec3( 0.0 );
#ifdef USE_CLEARCOAT
	geometryClearcoatNormal = clearcoatNormal;
#endif
#ifdef USE_IRIDESCENCE
	float dotNVi = saturate( dot( normal, geometryViewDir ) );
	if ( material.iridescenceThickness == 0.0 ) {
		material.iridescence = 0.0;
	} else {
		material.iridescence = saturate( material.iridescence );
	}
	if ( material.iridescence > 0.0 ) {
		vec3 iridescenceFresnelDielectric = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor );
		vec3 iridescenceFresnelMetallic = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.diffuseColor );
		material.iridescenceFresnel = mix( iridescenceFresnelDielectric, iridescenceFresnelMetallic, material.metalness );
		material.iridescenceF0Dielectric = Schlick_to_F0( iridescenceFresnelDielectric, 1.0, dotNVi );
		material.iridescenceF0Metallic = Schlick_to_F0( iridescenceFresnelMetallic, 1.0, dotNVi );
	}
#endif
#ifdef STANDARD
	float dotNVms = saturate( dot( geometryNormal, geometryViewDir ) );
	material.dfg = texture2D( dfgLUT, vec2( material.roughness, dotNVms ) ).rg;
	#if ( NUM_SUN_LIGHTS > 0 || NUM_DIR_LIGHTS > 0 || NUM_POINT_LIGHTS > 0 || NUM_SPOT_LIGHTS > 0 )
		float EssMs = material.dfg.x + material.dfg.y;
		material.multiScatteringCompensation = 1.0 + material.specularColorBlended * ( 1.0 / EssMs - 1.0 );
	#endif
#endif
IncidentLight directLight;
#if ( NUM_POINT_LIGHTS > 0 ) && defined( RE_Direct )
	PointLight pointLight;
	#if defined( USE_SHADOWMAP ) && NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
		pointLight = pointLights[ i ];
		getPointLightInfo( pointLight, geometryPosition, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_POINT_LIGHT_SHADOWS ) && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
		pointLightShadow = pointLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getPointShadow( pointShadowMap[ i ], pointLightShadow.shadowMapSize, pointLightShadow.shadowIntensity, pointLightShadow.shadowBias, pointLightShadow.shadowRadius, vPointShadowCoord[ i ], pointLightShadow.shadowCameraNear, pointLightShadow.shadowCameraFar ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SPOT_LIGHTS > 0 ) && defined( RE_Direct )
	SpotLight spotLight;
	vec4 spotColor;
	vec3 spotLightCoord;
	bool inSpotLightMap;
	#if defined( USE_SHADOWMAP ) && NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
		spotLight = spotLights[ i ];
		getSpotLightInfo( spotLight, geometryPosition, directLight );
		#if ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#define SPOT_LIGHT_MAP_INDEX UNROLLED_LOOP_INDEX
		#elif ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		#define SPOT_LIGHT_MAP_INDEX NUM_SPOT_LIGHT_MAPS
		#else
		#define SPOT_LIGHT_MAP_INDEX ( UNROLLED_LOOP_INDEX - NUM_SPOT_LIGHT_SHADOWS + NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#endif
		#if ( SPOT_LIGHT_MAP_INDEX < NUM_SPOT_LIGHT_MAPS )
			spotLightCoord = vSpotLightCoord[ i ].xyz / vSpotLightCoord[ i ].w;
			inSpotLightMap = all( lessThan( abs( spotLightCoord * 2. - 1. ), vec3( 1.0 ) ) );
			spotColor = texture2D( spotLightMap[ SPOT_LIGHT_MAP_INDEX ], spotLightCoord.xy );
			directLight.color = inSpotLightMap ? directLight.color * spotColor.rgb : directLight.color;
		#endif
		#undef SPOT_LIGHT_MAP_INDEX
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		spotLightShadow = spotLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( spotShadowMap[ i ], spotLightShadow.shadowMapSize, spotLightShadow.shadowIntensity, spotLightShadow.shadowBias, spotLightShadow.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SUN_LIGHTS > 0 ) && defined( RE_Direct )
	SunLight sunLight;
	#if defined( USE_SHADOWMAP ) && NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHTS; i ++ ) {
		sunLight = sunLights[ i ];
		getSunLightInfo( sunLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SUN_LIGHT_SHADOWS )
		sunLightShadow = sunLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getSunShadow( sunShadowMap[ i ], sunLightShadow, UNROLLED_LOOP_INDEX ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_DIR_LIGHTS > 0 ) && defined( RE_Direct )
	DirectionalLight directionalLight;
	#if defined( USE_SHADOWMAP ) && NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
		directionalLight = directionalLights[ i ];
		getDirectionalLightInfo( directionalLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_DIR_LIGHT_SHADOWS )
		directionalLightShadow = directionalLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], directionalLightShadow.shadowMapSize, directionalLightShadow.shadowIntensity, directionalLightShadow.shadowBias, directionalLightShadow.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_RECT_AREA_LIGHTS > 0 ) && defined( RE_Direct_RectArea )
	RectAreaLight rectAreaLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_RECT_AREA_LIGHTS; i ++ ) {
		rectAreaLight = rectAreaLights[ i ];
		RE_Direct_RectArea( rectAreaLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if defined( RE_IndirectDiffuse )
	vec3 iblIrradiance = vec3( 0.0 );
	vec3 irradiance = getAmbientLightIrradiance( ambientLightColor );
	#if defined( USE_LIGHT_PROBES )
		irradiance += getLightProbeIrradiance( lightProbe, geometryNormal );
	#endif
	#if ( NUM_HEMI_LIGHTS > 0 )
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_HEMI_LIGHTS; i ++ ) {
			irradiance += getHemisphereLightIrradiance( hemisphereLights[ i ], geometryNormal );
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_LIGHT_PROBE_GRIDS > 0
		vec3 probeWorldPos = ( ( vec4( geometryPosition, 1.0 ) - viewMatrix[ 3 ] ) * viewMatrix ).xyz;
		vec3 probeWorldNormal = transformNormalByInverseViewMatrix( geometryNormal, viewMatrix );
		int probeGrid = - 1;
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( isInsideLightProbeGrid( probeWorldPos, probeWorldNormal, probesMin[ i ], probesMax[ i ], probesResolution[ i ] ) ) probeGrid = UNROLLED_LOOP_INDEX;
		}
		#pragma unroll_loop_end
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( probeGrid == UNROLLED_LOOP_INDEX ) irradiance += getLightProbeGridIrradiance( probesSH[ i ], probesMin[ i ], probesMax[ i ], probesResolution[ i ], probeWorldPos, probeWorldNormal );
		}
		#pragma unroll_loop_end
	#endif
#endif
#if defined( RE_IndirectSpecular )
	vec3 radiance = vec3( 0.0 );
	vec3 clearcoatRadiance = vec3( 0.0 );
#endif`,Ex=`#if defined( RE_IndirectDiffuse )
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;
		irradiance += lightMapIrradiance;
	#endif
	#if defined( USE_ENVMAP ) && defined( ENVMAP_TYPE_PMREM )
		#if defined( STANDARD ) || defined( LAMBERT ) || defined( PHONG )
			iblIrradiance += getIBLIrradiance( geometryNormal );
		#endif
	#endif
#endif
#if defined( USE_ENVMAP ) && defined( RE_IndirectSpecular )
	#ifdef USE_ANISOTROPY
		vec3 iblRadiance = getIBLAnisotropyRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
	#else
		vec3 iblRadiance = getIBLRadiance( geometryViewDir, geometryNormal, material.roughness );
	#endif
	#ifdef USE_RETROREFLECTION
		#ifdef USE_ANISOTROPY
			vec3 retroIBLRadiance = getIBLAnisotropyRetroRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
		#else
			vec3 retroIBLRadiance = getIBLRetroRadiance( geometryViewDir, geometryNormal, material.roughness );
		#endif
		iblRadiance = mix( iblRadiance, retroIBLRadiance, saturate( material.retroreflectivity ) );
	#endif
	radiance += iblRadiance;
	#ifdef USE_CLEARCOAT
		clearcoatRadiance += getIBLRadiance( geometryViewDir, geometryClearcoatNormal, material.clearcoatRoughness );
	#endif
#endif`,Tx=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,Ix=`#if NUM_LIGHT_PROBE_GRIDS > 0
uniform highp sampler3D probesSH[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMin[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMax[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesResolution[ NUM_LIGHT_PROBE_GRIDS ];
bool isInsideLightProbeGrid( vec3 worldPos, vec3 worldNormal, vec3 probesMin, vec3 probesMax, vec3 probesResolution ) {
	vec3 spacing = ( probesMax - probesMin ) / probesResolution;
	vec3 samplePos = worldPos + worldNormal * spacing * 0.5;
	vec3 margin = spacing * 0.01;
	return all( greaterThanEqual( samplePos, probesMin - margin ) ) && all( lessThanEqual( samplePos, probesMax + margin ) );
}
vec3 getLightProbeGridIrradiance( highp sampler3D probesSH, vec3 probesMin, vec3 probesMax, vec3 probesResolution, vec3 worldPos, vec3 worldNormal ) {
	vec3 res = probesResolution;
	vec3 gridRange = probesMax - probesMin;
	vec3 probeSpacing = gridRange / res;
	vec3 samplePos = worldPos + worldNormal * probeSpacing * 0.5;
	vec3 uvw = clamp( ( samplePos - probesMin ) / gridRange, 0.5 / res, 1.0 - 0.5 / res );
	float nz          = res.z;
	float paddedSlices = nz + 2.0;
	float atlasDepth  = 7.0 * paddedSlices;
	float uvZBase     = uvw.z * nz + 1.0;
	vec4 s0 = texture( probesSH, vec3( uvw.xy, ( uvZBase                       ) / atlasDepth ) );
	vec4 s1 = texture( probesSH, vec3( uvw.xy, ( uvZBase +       paddedSlices   ) / atlasDepth ) );
	vec4 s2 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 2.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s3 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 3.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s4 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 4.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s5 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 5.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s6 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 6.0 * paddedSlices   ) / atlasDepth ) );
	vec3 c0 = s0.xyz;
	vec3 c1 = vec3( s0.w, s1.xy );
	vec3 c2 = vec3( s1.zw, s2.x );
	vec3 c3 = s2.yzw;
	vec3 c4 = s3.xyz;
	vec3 c5 = vec3( s3.w, s4.xy );
	vec3 c6 = vec3( s4.zw, s5.x );
	vec3 c7 = s5.yzw;
	vec3 c8 = s6.xyz;
	float x = worldNormal.x, y = worldNormal.y, z = worldNormal.z;
	vec3 result = c0 * 0.886227;
	result += c1 * 2.0 * 0.511664 * y;
	result += c2 * 2.0 * 0.511664 * z;
	result += c3 * 2.0 * 0.511664 * x;
	result += c4 * 2.0 * 0.429043 * x * y;
	result += c5 * 2.0 * 0.429043 * y * z;
	result += c6 * ( 0.743125 * z * z - 0.247708 );
	result += c7 * 2.0 * 0.429043 * x * z;
	result += c8 * 0.429043 * ( x * x - y * y );
	return max( result, vec3( 0.0 ) );
}
#endif`,Rx=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,Cx=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,Nx=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,Px=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,Lx=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,Dx=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,Ux=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	#if defined( USE_POINTS_UV )
		vec2 uv = vUv;
	#else
		vec2 uv = ( uvTransform * vec3( gl_PointCoord.x, 1.0 - gl_PointCoord.y, 1 ) ).xy;
	#endif
#endif
#ifdef USE_MAP
	diffuseColor *= texture2D( map, uv );
#endif
#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, uv ).g;
#endif`,Ox=`#if defined( USE_POINTS_UV )
	varying vec2 vUv;
#else
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		uniform mat3 uvTransform;
	#endif
#endif
#ifdef USE_MAP
	uniform sampler2D map;
#endif
#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,Fx=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,Bx=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,kx=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,zx=`#if defined( USE_MORPHCOLORS )
	#if defined( USE_COLOR_ALPHA )
		vColor *= morphTargetBaseInfluence;
	#elif defined( USE_COLOR )
		vColor.rgb *= morphTargetBaseInfluence;
	#endif
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		#if defined( USE_COLOR_ALPHA )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ) * morphTargetInfluences[ i ];
		#elif defined( USE_COLOR )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor.rgb += getMorph( gl_VertexID, i, 2 ).rgb * morphTargetInfluences[ i ];
		#endif
	}
#endif`,Vx=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Hx=`#ifdef USE_MORPHTARGETS
	#ifndef USE_INSTANCING_MORPH
		uniform float morphTargetBaseInfluence;
		uniform float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	#endif
	uniform sampler2DArray morphTargetsTexture;
	uniform ivec2 morphTargetsTextureSize;
	vec4 getMorph( const in int vertexIndex, const in int morphTargetIndex, const in int offset ) {
		int texelIndex = vertexIndex * MORPHTARGETS_TEXTURE_STRIDE + offset;
		int y = texelIndex / morphTargetsTextureSize.x;
		int x = texelIndex - y * morphTargetsTextureSize.x;
		ivec3 morphUV = ivec3( x, y, morphTargetIndex );
		return texelFetch( morphTargetsTexture, morphUV, 0 );
	}
#endif`,Gx=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Wx=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#ifdef FLAT_SHADED
	vec3 fdx = dFdx( vViewPosition );
	vec3 fdy = dFdy( vViewPosition );
	vec3 normal = normalize( cross( fdx, fdy ) );
#else
	vec3 normal = normalize( vNormal );
	#ifdef DOUBLE_SIDED
		normal *= faceDirection;
	#endif
#endif
#if defined( USE_NORMALMAP_TANGENTSPACE ) || defined( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY )
	#ifdef USE_TANGENT
		mat3 tbn = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn = getTangentFrame( - vViewPosition, normal,
		#if defined( USE_NORMALMAP )
			vNormalMapUv
		#elif defined( USE_CLEARCOAT_NORMALMAP )
			vClearcoatNormalMapUv
		#else
			vUv
		#endif
		);
	#endif
	#ifdef DOUBLE_SIDED
		tbn[0] *= faceDirection;
		tbn[1] *= faceDirection;
	#endif
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	#ifdef USE_TANGENT
		mat3 tbn2 = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn2 = getTangentFrame( - vViewPosition, normal, vClearcoatNormalMapUv );
	#endif
	#ifdef DOUBLE_SIDED
		tbn2[0] *= faceDirection;
		tbn2[1] *= faceDirection;
	#endif
#endif
vec3 nonPerturbedNormal = normal;`,jx=`#ifdef USE_NORMALMAP_OBJECTSPACE
	normal = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#ifdef FLIP_SIDED
		normal = - normal;
	#endif
	#ifdef DOUBLE_SIDED
		normal = normal * faceDirection;
	#endif
	normal = normalize( normalMatrix * normal );
#elif defined( USE_NORMALMAP_TANGENTSPACE )
	vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#if defined( USE_PACKED_NORMALMAP )
		mapN = vec3( mapN.xy, sqrt( saturate( 1.0 - dot( mapN.xy, mapN.xy ) ) ) );
	#endif
	mapN.xy *= normalScale;
	normal = normalize( tbn * mapN );
#elif defined( USE_BUMPMAP )
	normal = perturbNormalArb( - vViewPosition, normal, dHdxy_fwd(), faceDirection );
#endif`,Xx=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,qx=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,Yx=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,Jx=`#ifdef USE_NORMALMAP
	uniform sampler2D normalMap;
	uniform vec2 normalScale;
#endif
#ifdef USE_NORMALMAP_OBJECTSPACE
	uniform mat3 normalMatrix;
#endif
#if ! defined ( USE_TANGENT ) && ( defined ( USE_NORMALMAP_TANGENTSPACE ) || defined ( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY ) )
	mat3 getTangentFrame( vec3 eye_pos, vec3 surf_norm, vec2 uv ) {
		vec3 q0 = dFdx( eye_pos.xyz );
		vec3 q1 = dFdy( eye_pos.xyz );
		vec2 st0 = dFdx( uv.st );
		vec2 st1 = dFdy( uv.st );
		vec3 N = surf_norm;
		vec3 q1perp = cross( q1, N );
		vec3 q0perp = cross( N, q0 );
		vec3 T = q1perp * st0.x + q0perp * st1.x;
		vec3 B = q1perp * st0.y + q0perp * st1.y;
		float det = max( dot( T, T ), dot( B, B ) );
		float scale = ( det == 0.0 ) ? 0.0 : inversesqrt( det );
		return mat3( T * scale, B * scale, N );
	}
#endif`,Kx=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,Zx=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,Qx=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,$x=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,t0=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,e0=`vec3 packNormalToRGB( const in vec3 normal ) {
	return normalize( normal ) * 0.5 + 0.5;
}
vec3 unpackRGBToNormal( const in vec3 rgb ) {
	return 2.0 * rgb.xyz - 1.0;
}
const float PackUpscale = 256. / 255.;const float UnpackDownscale = 255. / 256.;const float ShiftRight8 = 1. / 256.;
const float Inv255 = 1. / 255.;
const vec4 PackFactors = vec4( 1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0 );
const vec2 UnpackFactors2 = vec2( UnpackDownscale, 1.0 / PackFactors.g );
const vec3 UnpackFactors3 = vec3( UnpackDownscale / PackFactors.rg, 1.0 / PackFactors.b );
const vec4 UnpackFactors4 = vec4( UnpackDownscale / PackFactors.rgb, 1.0 / PackFactors.a );
vec4 packDepthToRGBA( const in float v ) {
	if( v <= 0.0 )
		return vec4( 0., 0., 0., 0. );
	if( v >= 1.0 )
		return vec4( 1., 1., 1., 1. );
	float vuf;
	float af = modf( v * PackFactors.a, vuf );
	float bf = modf( vuf * ShiftRight8, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec4( vuf * Inv255, gf * PackUpscale, bf * PackUpscale, af );
}
vec3 packDepthToRGB( const in float v ) {
	if( v <= 0.0 )
		return vec3( 0., 0., 0. );
	if( v >= 1.0 )
		return vec3( 1., 1., 1. );
	float vuf;
	float bf = modf( v * PackFactors.b, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec3( vuf * Inv255, gf * PackUpscale, bf );
}
vec2 packDepthToRG( const in float v ) {
	if( v <= 0.0 )
		return vec2( 0., 0. );
	if( v >= 1.0 )
		return vec2( 1., 1. );
	float vuf;
	float gf = modf( v * 256., vuf );
	return vec2( vuf * Inv255, gf );
}
float unpackRGBAToDepth( const in vec4 v ) {
	return dot( v, UnpackFactors4 );
}
float unpackRGBToDepth( const in vec3 v ) {
	return dot( v, UnpackFactors3 );
}
float unpackRGToDepth( const in vec2 v ) {
	return v.r * UnpackFactors2.r + v.g * UnpackFactors2.g;
}
vec4 pack2HalfToRGBA( const in vec2 v ) {
	vec4 r = vec4( v.x, fract( v.x * 255.0 ), v.y, fract( v.y * 255.0 ) );
	return vec4( r.x - r.y / 255.0, r.y, r.z - r.w / 255.0, r.w );
}
vec2 unpackRGBATo2Half( const in vec4 v ) {
	return vec2( v.x + ( v.y / 255.0 ), v.z + ( v.w / 255.0 ) );
}
float viewZToOrthographicDepth( const in float viewZ, const in float near, const in float far ) {
	return ( viewZ + near ) / ( near - far );
}
float orthographicDepthToViewZ( const in float depth, const in float near, const in float far ) {
	#ifdef USE_REVERSED_DEPTH_BUFFER
	
		return depth * ( far - near ) - far;
	#else
		return depth * ( near - far ) - near;
	#endif
}
float viewZToPerspectiveDepth( const in float viewZ, const in float near, const in float far ) {
	return ( ( near + viewZ ) * far ) / ( ( far - near ) * viewZ );
}
float perspectiveDepthToViewZ( const in float depth, const in float near, const in float far ) {
	
	#ifdef USE_REVERSED_DEPTH_BUFFER
		return ( near * far ) / ( ( near - far ) * depth - near );
	#else
		return ( near * far ) / ( ( far - near ) * depth - far );
	#endif
}`,n0=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,i0=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,a0=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,s0=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,r0=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,o0=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,c0=`#if NUM_SPOT_LIGHT_COORDS > 0
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#if NUM_SPOT_LIGHT_MAPS > 0
	uniform sampler2D spotLightMap[ NUM_SPOT_LIGHT_MAPS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		#define SUN_LIGHT_CASCADES 2
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#else
			uniform sampler2D sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#endif
		uniform mat4 sunShadowMatrix[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		uniform vec4 sunShadowCascade[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
		struct SunLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SunLightShadow sunLightShadows[ NUM_SUN_LIGHT_SHADOWS ];
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#else
			uniform sampler2D directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#endif
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#else
			uniform sampler2D spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#endif
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform samplerCubeShadow pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#elif defined( SHADOWMAP_TYPE_BASIC )
			uniform samplerCube pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#endif
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float interleavedGradientNoise( vec2 position ) {
			return fract( 52.9829189 * fract( dot( position, vec2( 0.06711056, 0.00583715 ) ) ) );
		}
		vec2 vogelDiskSample( int sampleIndex, int samplesCount, float phi ) {
			const float goldenAngle = 2.399963229728653;
			float r = sqrt( ( float( sampleIndex ) + 0.5 ) / float( samplesCount ) );
			float theta = float( sampleIndex ) * goldenAngle + phi;
			return vec2( cos( theta ), sin( theta ) ) * r;
		}
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float getShadow( sampler2DShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
				vec2 radius = shadowRadius * texelSize;
				float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
				shadow = (
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 0, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 1, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 2, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 3, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 4, 5, phi ) * radius, shadowCoord.z ) )
				) * 0.2;
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#elif defined( SHADOWMAP_TYPE_VSM )
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 distribution = texture2D( shadowMap, shadowCoord.xy ).rg;
				float mean = distribution.x;
				float variance = distribution.y * distribution.y;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					float hard_shadow = step( mean, shadowCoord.z );
				#else
					float hard_shadow = step( shadowCoord.z, mean );
				#endif
				
				if ( hard_shadow == 1.0 ) {
					shadow = 1.0;
				} else {
					variance = max( variance, 0.0000001 );
					float d = shadowCoord.z - mean;
					float p_max = variance / ( variance + d * d );
					p_max = clamp( ( p_max - 0.3 ) / 0.65, 0.0, 1.0 );
					shadow = max( hard_shadow, p_max );
				}
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#else
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				float depth = texture2D( shadowMap, shadowCoord.xy ).r;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					shadow = step( depth, shadowCoord.z );
				#else
					shadow = step( shadowCoord.z, depth );
				#endif
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#endif
	#if NUM_SUN_LIGHT_SHADOWS > 0
		float getSunShadow(
			#if defined( SHADOWMAP_TYPE_PCF )
				sampler2DShadow shadowMap,
			#else
				sampler2D shadowMap,
			#endif
			SunLightShadow sunLightShadow,
			int shadowIndex
		) {
			vec4 shadowWorldPosition = vec4( vSunShadowWorldPosition.xyz + vSunShadowWorldNormal * sunLightShadow.shadowNormalBias, 1.0 );
			float viewDepth = vSunShadowWorldPosition.w;
			int cascadeOffset = shadowIndex * SUN_LIGHT_CASCADES;
			float shadow = 1.0;
			for ( int i = SUN_LIGHT_CASCADES - 1; i >= 0; i -- ) {
				vec4 cascade = sunShadowCascade[ cascadeOffset + i ];
				if ( viewDepth >= cascade.x && viewDepth < cascade.y ) {
					float cascadeShadow = getShadow(
						shadowMap,
						sunLightShadow.shadowMapSize,
						sunLightShadow.shadowIntensity,
						sunLightShadow.shadowBias,
						sunLightShadow.shadowRadius,
						sunShadowMatrix[ cascadeOffset + i ] * shadowWorldPosition
					);
					shadow = mix( cascadeShadow, shadow, smoothstep( cascade.z, cascade.y, viewDepth ) );
				}
			}
			return shadow;
		}
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
	#if defined( SHADOWMAP_TYPE_PCF )
	float getPointShadow( samplerCubeShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 bd3D = normalize( lightToPosition );
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float lightDistance = length( lightToPosition );
			float depthRange = shadowCameraFar - shadowCameraNear;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				float depthA = - shadowCameraNear / depthRange - shadowBias;
				float depthB = shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#else
				float depthA = shadowCameraFar / depthRange + shadowBias;
				float depthB = - shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#endif
			float texelSize = shadowRadius / shadowMapSize.x;
			vec3 absDir = abs( bd3D );
			vec3 tangent = absDir.x > absDir.z ? vec3( 0.0, 1.0, 0.0 ) : vec3( 1.0, 0.0, 0.0 );
			tangent = normalize( cross( bd3D, tangent ) );
			vec3 bitangent = cross( bd3D, tangent );
			float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
			shadow = 0.0;
			for ( int i = 0; i < 5; i ++ ) {
				vec2 offset = vogelDiskSample( i, 5, phi );
				vec3 direction = bd3D + ( tangent * offset.x + bitangent * offset.y ) * texelSize;
				vec3 absDirection = abs( direction );
				float dp = depthA + depthB / max( max( absDirection.x, absDirection.y ), absDirection.z );
				shadow += texture( shadowMap, vec4( direction, dp ) );
			}
			shadow *= 0.2;
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#elif defined( SHADOWMAP_TYPE_BASIC )
	float getPointShadow( samplerCube shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float dp = ( shadowCameraFar * ( viewSpaceZ - shadowCameraNear ) ) / ( viewSpaceZ * ( shadowCameraFar - shadowCameraNear ) );
			dp += shadowBias;
			vec3 bd3D = normalize( lightToPosition );
			float depth = textureCube( shadowMap, bd3D ).r;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				depth = 1.0 - depth;
			#endif
			shadow = step( dp, depth );
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#endif
	#endif
#endif`,l0=`#if NUM_SPOT_LIGHT_COORDS > 0
	uniform mat4 spotLightMatrix[ NUM_SPOT_LIGHT_COORDS ];
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform mat4 directionalShadowMatrix[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform mat4 pointShadowMatrix[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
#endif`,h0=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
	#ifdef HAS_NORMAL
		vec3 shadowWorldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
	#else
		vec3 shadowWorldNormal = vec3( 0.0 );
	#endif
	vec4 shadowWorldPosition;
#endif
#if defined( USE_SHADOWMAP )
	#if NUM_SUN_LIGHT_SHADOWS > 0
		vSunShadowWorldPosition = vec4( worldPosition.xyz, - mvPosition.z );
		vSunShadowWorldNormal = shadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * directionalLightShadows[ i ].shadowNormalBias, 0 );
			vDirectionalShadowCoord[ i ] = directionalShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * pointLightShadows[ i ].shadowNormalBias, 0 );
			vPointShadowCoord[ i ] = pointShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
#endif
#if NUM_SPOT_LIGHT_COORDS > 0
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_COORDS; i ++ ) {
		shadowWorldPosition = worldPosition;
		#if ( defined( USE_SHADOWMAP ) && UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
			shadowWorldPosition.xyz += shadowWorldNormal * spotLightShadows[ i ].shadowNormalBias;
		#endif
		vSpotLightCoord[ i ] = spotLightMatrix[ i ] * shadowWorldPosition;
	}
	#pragma unroll_loop_end
#endif`,d0=`float getShadowMask() {
	float shadow = 1.0;
	#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHT_SHADOWS; i ++ ) {
		sunLight = sunLightShadows[ i ];
		shadow *= receiveShadow ? getSunShadow( sunShadowMap[ i ], sunLight, UNROLLED_LOOP_INDEX ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
		directionalLight = directionalLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( directionalShadowMap[ i ], directionalLight.shadowMapSize, directionalLight.shadowIntensity, directionalLight.shadowBias, directionalLight.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_SHADOWS; i ++ ) {
		spotLight = spotLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( spotShadowMap[ i ], spotLight.shadowMapSize, spotLight.shadowIntensity, spotLight.shadowBias, spotLight.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0 && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
	PointLightShadow pointLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
		pointLight = pointLightShadows[ i ];
		shadow *= receiveShadow ? getPointShadow( pointShadowMap[ i ], pointLight.shadowMapSize, pointLight.shadowIntensity, pointLight.shadowBias, pointLight.shadowRadius, vPointShadowCoord[ i ], pointLight.shadowCameraNear, pointLight.shadowCameraFar ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#endif
	return shadow;
}`,u0=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,f0=`#ifdef USE_SKINNING
	uniform mat4 bindMatrix;
	uniform mat4 bindMatrixInverse;
	uniform highp sampler2D boneTexture;
	mat4 getBoneMatrix( const in float i ) {
		int size = textureSize( boneTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( boneTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( boneTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( boneTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( boneTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
#endif`,p0=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,m0=`#ifdef USE_SKINNING
	mat4 skinMatrix = mat4( 0.0 );
	skinMatrix += skinWeight.x * boneMatX;
	skinMatrix += skinWeight.y * boneMatY;
	skinMatrix += skinWeight.z * boneMatZ;
	skinMatrix += skinWeight.w * boneMatW;
	skinMatrix = bindMatrixInverse * skinMatrix * bindMatrix;
	objectNormal = vec4( skinMatrix * vec4( objectNormal, 0.0 ) ).xyz;
	#ifdef USE_TANGENT
		objectTangent = vec4( skinMatrix * vec4( objectTangent, 0.0 ) ).xyz;
	#endif
#endif`,g0=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,b0=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,x0=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,y0=`#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
uniform float toneMappingExposure;
vec3 LinearToneMapping( vec3 color ) {
	return saturate( toneMappingExposure * color );
}
vec3 ReinhardToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	return saturate( color / ( vec3( 1.0 ) + color ) );
}
vec3 CineonToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	color = max( vec3( 0.0 ), color - 0.004 );
	return pow( ( color * ( 6.2 * color + 0.5 ) ) / ( color * ( 6.2 * color + 1.7 ) + 0.06 ), vec3( 2.2 ) );
}
vec3 RRTAndODTFit( vec3 v ) {
	vec3 a = v * ( v + 0.0245786 ) - 0.000090537;
	vec3 b = v * ( 0.983729 * v + 0.4329510 ) + 0.238081;
	return a / b;
}
vec3 ACESFilmicToneMapping( vec3 color ) {
	const mat3 ACESInputMat = mat3(
		vec3( 0.59719, 0.07600, 0.02840 ),		vec3( 0.35458, 0.90834, 0.13383 ),
		vec3( 0.04823, 0.01566, 0.83777 )
	);
	const mat3 ACESOutputMat = mat3(
		vec3(  1.60475, -0.10208, -0.00327 ),		vec3( -0.53108,  1.10813, -0.07276 ),
		vec3( -0.07367, -0.00605,  1.07602 )
	);
	color *= toneMappingExposure / 0.6;
	color = ACESInputMat * color;
	color = RRTAndODTFit( color );
	color = ACESOutputMat * color;
	return saturate( color );
}
const mat3 LINEAR_REC2020_TO_LINEAR_SRGB = mat3(
	vec3( 1.6605, - 0.1246, - 0.0182 ),
	vec3( - 0.5876, 1.1329, - 0.1006 ),
	vec3( - 0.0728, - 0.0083, 1.1187 )
);
const mat3 LINEAR_SRGB_TO_LINEAR_REC2020 = mat3(
	vec3( 0.6274, 0.0691, 0.0164 ),
	vec3( 0.3293, 0.9195, 0.0880 ),
	vec3( 0.0433, 0.0113, 0.8956 )
);
vec3 agxDefaultContrastApprox( vec3 x ) {
	vec3 x2 = x * x;
	vec3 x4 = x2 * x2;
	return + 15.5 * x4 * x2
		- 40.14 * x4 * x
		+ 31.96 * x4
		- 6.868 * x2 * x
		+ 0.4298 * x2
		+ 0.1191 * x
		- 0.00232;
}
vec3 AgXToneMapping( vec3 color ) {
	const mat3 AgXInsetMatrix = mat3(
		vec3( 0.856627153315983, 0.137318972929847, 0.11189821299995 ),
		vec3( 0.0951212405381588, 0.761241990602591, 0.0767994186031903 ),
		vec3( 0.0482516061458583, 0.101439036467562, 0.811302368396859 )
	);
	const mat3 AgXOutsetMatrix = mat3(
		vec3( 1.1271005818144368, - 0.1413297634984383, - 0.14132976349843826 ),
		vec3( - 0.11060664309660323, 1.157823702216272, - 0.11060664309660294 ),
		vec3( - 0.016493938717834573, - 0.016493938717834257, 1.2519364065950405 )
	);
	const float AgxMinEv = - 12.47393;	const float AgxMaxEv = 4.026069;
	color *= toneMappingExposure;
	color = LINEAR_SRGB_TO_LINEAR_REC2020 * color;
	color = AgXInsetMatrix * color;
	color = max( color, 1e-10 );	color = log2( color );
	color = ( color - AgxMinEv ) / ( AgxMaxEv - AgxMinEv );
	color = clamp( color, 0.0, 1.0 );
	color = agxDefaultContrastApprox( color );
	color = AgXOutsetMatrix * color;
	color = pow( max( vec3( 0.0 ), color ), vec3( 2.2 ) );
	color = LINEAR_REC2020_TO_LINEAR_SRGB * color;
	color = clamp( color, 0.0, 1.0 );
	return color;
}
vec3 NeutralToneMapping( vec3 color ) {
	const float StartCompression = 0.8 - 0.04;
	const float Desaturation = 0.15;
	color *= toneMappingExposure;
	float x = min( color.r, min( color.g, color.b ) );
	float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
	color -= offset;
	float peak = max( color.r, max( color.g, color.b ) );
	if ( peak < StartCompression ) return color;
	float d = 1. - StartCompression;
	float newPeak = 1. - d * d / ( peak + d - StartCompression );
	color *= newPeak / peak;
	float g = 1. - 1. / ( Desaturation * ( peak - newPeak ) + 1. );
	return mix( color, vec3( newPeak ), g );
}
vec3 CustomToneMapping( vec3 color ) { return color; }`,_0=`#ifdef USE_TRANSMISSION
	material.transmission = transmission;
	material.transmissionAlpha = 1.0;
	material.thickness = thickness;
	material.attenuationDistance = attenuationDistance;
	material.attenuationColor = attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		material.transmission *= texture2D( transmissionMap, vTransmissionMapUv ).r;
	#endif
	#ifdef USE_THICKNESSMAP
		material.thickness *= texture2D( thicknessMap, vThicknessMapUv ).g;
	#endif
	vec3 pos = vWorldPosition;
	vec3 v = normalize( cameraPosition - pos );
	vec3 n = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec4 transmitted = getIBLVolumeRefraction(
		n, v, material.roughness, material.diffuseContribution, material.specularColorBlended, material.specularF90,
		pos, modelMatrix, viewMatrix, projectionMatrix, material.dispersion, material.ior, material.thickness,
		material.attenuationColor, material.attenuationDistance );
	material.transmissionAlpha = mix( material.transmissionAlpha, transmitted.a, material.transmission );
	totalDiffuse = mix( totalDiffuse, transmitted.rgb, material.transmission );
#endif`,v0=`#ifdef USE_TRANSMISSION
	uniform float transmission;
	uniform float thickness;
	uniform float attenuationDistance;
	uniform vec3 attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		uniform sampler2D transmissionMap;
	#endif
	#ifdef USE_THICKNESSMAP
		uniform sampler2D thicknessMap;
	#endif
	uniform vec2 transmissionSamplerSize;
	uniform sampler2D transmissionSamplerMap;
	uniform mat4 modelMatrix;
	uniform mat4 projectionMatrix;
	varying vec3 vWorldPosition;
	float w0( float a ) {
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - a + 3.0 ) - 3.0 ) + 1.0 );
	}
	float w1( float a ) {
		return ( 1.0 / 6.0 ) * ( a *  a * ( 3.0 * a - 6.0 ) + 4.0 );
	}
	float w2( float a ){
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - 3.0 * a + 3.0 ) + 3.0 ) + 1.0 );
	}
	float w3( float a ) {
		return ( 1.0 / 6.0 ) * ( a * a * a );
	}
	float g0( float a ) {
		return w0( a ) + w1( a );
	}
	float g1( float a ) {
		return w2( a ) + w3( a );
	}
	float h0( float a ) {
		return - 1.0 + w1( a ) / ( w0( a ) + w1( a ) );
	}
	float h1( float a ) {
		return 1.0 + w3( a ) / ( w2( a ) + w3( a ) );
	}
	vec4 bicubic( sampler2D tex, vec2 uv, vec4 texelSize, float lod ) {
		uv = uv * texelSize.zw + 0.5;
		vec2 iuv = floor( uv );
		vec2 fuv = fract( uv );
		float g0x = g0( fuv.x );
		float g1x = g1( fuv.x );
		float h0x = h0( fuv.x );
		float h1x = h1( fuv.x );
		float h0y = h0( fuv.y );
		float h1y = h1( fuv.y );
		vec2 p0 = ( vec2( iuv.x + h0x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p1 = ( vec2( iuv.x + h1x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p2 = ( vec2( iuv.x + h0x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		vec2 p3 = ( vec2( iuv.x + h1x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		return g0( fuv.y ) * ( g0x * textureLod( tex, p0, lod ) + g1x * textureLod( tex, p1, lod ) ) +
			g1( fuv.y ) * ( g0x * textureLod( tex, p2, lod ) + g1x * textureLod( tex, p3, lod ) );
	}
	vec4 textureBicubic( sampler2D sampler, vec2 uv, float lod ) {
		vec2 fLodSize = vec2( textureSize( sampler, int( lod ) ) );
		vec2 cLodSize = vec2( textureSize( sampler, int( lod + 1.0 ) ) );
		vec2 fLodSizeInv = 1.0 / fLodSize;
		vec2 cLodSizeInv = 1.0 / cLodSize;
		vec4 fSample = bicubic( sampler, uv, vec4( fLodSizeInv, fLodSize ), floor( lod ) );
		vec4 cSample = bicubic( sampler, uv, vec4( cLodSizeInv, cLodSize ), ceil( lod ) );
		return mix( fSample, cSample, fract( lod ) );
	}
	vec3 getVolumeTransmissionRay( const in vec3 n, const in vec3 v, const in float thickness, const in float ior, const in mat4 modelMatrix ) {
		vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );
		vec3 modelScale;
		modelScale.x = length( vec3( modelMatrix[ 0 ].xyz ) );
		modelScale.y = length( vec3( modelMatrix[ 1 ].xyz ) );
		modelScale.z = length( vec3( modelMatrix[ 2 ].xyz ) );
		return normalize( refractionVector ) * thickness * modelScale;
	}
	float applyIorToRoughness( const in float roughness, const in float ior ) {
		return roughness * clamp( ior * 2.0 - 2.0, 0.0, 1.0 );
	}
	vec4 getTransmissionSample( const in vec2 fragCoord, const in float roughness, const in float ior ) {
		float lod = log2( transmissionSamplerSize.x ) * applyIorToRoughness( roughness, ior );
		return textureBicubic( transmissionSamplerMap, fragCoord.xy, lod );
	}
	vec3 volumeAttenuation( const in float transmissionDistance, const in vec3 attenuationColor, const in float attenuationDistance ) {
		if ( isinf( attenuationDistance ) ) {
			return vec3( 1.0 );
		} else {
			vec3 attenuationCoefficient = -log( attenuationColor ) / attenuationDistance;
			vec3 transmittance = exp( - attenuationCoefficient * transmissionDistance );			return transmittance;
		}
	}
	vec4 getIBLVolumeRefraction( const in vec3 n, const in vec3 v, const in float roughness, const in vec3 diffuseColor,
		const in vec3 specularColor, const in float specularF90, const in vec3 position, const in mat4 modelMatrix,
		const in mat4 viewMatrix, const in mat4 projMatrix, const in float dispersion, const in float ior, const in float thickness,
		const in vec3 attenuationColor, const in float attenuationDistance ) {
		vec4 transmittedLight;
		vec3 transmittance;
		#ifdef USE_DISPERSION
			float halfSpread = ( ior - 1.0 ) * 0.025 * dispersion;
			vec3 iors = vec3( ior - halfSpread, ior, ior + halfSpread );
			for ( int i = 0; i < 3; i ++ ) {
				vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, iors[ i ], modelMatrix );
				vec3 refractedRayExit = position + transmissionRay;
				vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
				vec2 refractionCoords = ndcPos.xy / ndcPos.w;
				refractionCoords += 1.0;
				refractionCoords /= 2.0;
				vec4 transmissionSample = getTransmissionSample( refractionCoords, roughness, iors[ i ] );
				transmittedLight[ i ] = transmissionSample[ i ];
				transmittedLight.a += transmissionSample.a;
				transmittance[ i ] = diffuseColor[ i ] * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance )[ i ];
			}
			transmittedLight.a /= 3.0;
		#else
			vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, ior, modelMatrix );
			vec3 refractedRayExit = position + transmissionRay;
			vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
			vec2 refractionCoords = ndcPos.xy / ndcPos.w;
			refractionCoords += 1.0;
			refractionCoords /= 2.0;
			transmittedLight = getTransmissionSample( refractionCoords, roughness, ior );
			transmittance = diffuseColor * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance );
		#endif
		vec3 attenuatedColor = transmittance * transmittedLight.rgb;
		vec3 F = EnvironmentBRDF( n, v, specularColor, specularF90, roughness );
		float transmittanceFactor = ( transmittance.r + transmittance.g + transmittance.b ) / 3.0;
		return vec4( ( 1.0 - F ) * attenuatedColor, 1.0 - ( 1.0 - transmittedLight.a ) * transmittanceFactor );
	}
#endif`,M0=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_SPECULARMAP
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,S0=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	uniform mat3 mapTransform;
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	uniform mat3 alphaMapTransform;
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	uniform mat3 lightMapTransform;
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	uniform mat3 aoMapTransform;
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	uniform mat3 bumpMapTransform;
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	uniform mat3 normalMapTransform;
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_DISPLACEMENTMAP
	uniform mat3 displacementMapTransform;
	varying vec2 vDisplacementMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	uniform mat3 emissiveMapTransform;
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	uniform mat3 metalnessMapTransform;
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	uniform mat3 roughnessMapTransform;
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	uniform mat3 diffuseRoughnessMapTransform;
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	uniform mat3 anisotropyMapTransform;
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	uniform mat3 clearcoatMapTransform;
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform mat3 clearcoatNormalMapTransform;
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform mat3 clearcoatRoughnessMapTransform;
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	uniform mat3 sheenColorMapTransform;
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	uniform mat3 sheenRoughnessMapTransform;
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	uniform mat3 iridescenceMapTransform;
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform mat3 iridescenceThicknessMapTransform;
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SPECULARMAP
	uniform mat3 specularMapTransform;
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	uniform mat3 specularColorMapTransform;
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	uniform mat3 specularIntensityMapTransform;
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,w0=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	vUv = vec3( uv, 1 ).xy;
#endif
#ifdef USE_MAP
	vMapUv = ( mapTransform * vec3( MAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ALPHAMAP
	vAlphaMapUv = ( alphaMapTransform * vec3( ALPHAMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_LIGHTMAP
	vLightMapUv = ( lightMapTransform * vec3( LIGHTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_AOMAP
	vAoMapUv = ( aoMapTransform * vec3( AOMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_BUMPMAP
	vBumpMapUv = ( bumpMapTransform * vec3( BUMPMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_NORMALMAP
	vNormalMapUv = ( normalMapTransform * vec3( NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DISPLACEMENTMAP
	vDisplacementMapUv = ( displacementMapTransform * vec3( DISPLACEMENTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_EMISSIVEMAP
	vEmissiveMapUv = ( emissiveMapTransform * vec3( EMISSIVEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_METALNESSMAP
	vMetalnessMapUv = ( metalnessMapTransform * vec3( METALNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ROUGHNESSMAP
	vRoughnessMapUv = ( roughnessMapTransform * vec3( ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	vDiffuseRoughnessMapUv = ( diffuseRoughnessMapTransform * vec3( DIFFUSE_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ANISOTROPYMAP
	vAnisotropyMapUv = ( anisotropyMapTransform * vec3( ANISOTROPYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOATMAP
	vClearcoatMapUv = ( clearcoatMapTransform * vec3( CLEARCOATMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	vClearcoatNormalMapUv = ( clearcoatNormalMapTransform * vec3( CLEARCOAT_NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	vClearcoatRoughnessMapUv = ( clearcoatRoughnessMapTransform * vec3( CLEARCOAT_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCEMAP
	vIridescenceMapUv = ( iridescenceMapTransform * vec3( IRIDESCENCEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	vIridescenceThicknessMapUv = ( iridescenceThicknessMapTransform * vec3( IRIDESCENCE_THICKNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_COLORMAP
	vSheenColorMapUv = ( sheenColorMapTransform * vec3( SHEEN_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	vSheenRoughnessMapUv = ( sheenRoughnessMapTransform * vec3( SHEEN_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULARMAP
	vSpecularMapUv = ( specularMapTransform * vec3( SPECULARMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_COLORMAP
	vSpecularColorMapUv = ( specularColorMapTransform * vec3( SPECULAR_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	vSpecularIntensityMapUv = ( specularIntensityMapTransform * vec3( SPECULAR_INTENSITYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_TRANSMISSIONMAP
	vTransmissionMapUv = ( transmissionMapTransform * vec3( TRANSMISSIONMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_THICKNESSMAP
	vThicknessMapUv = ( thicknessMapTransform * vec3( THICKNESSMAP_UV, 1 ) ).xy;
#endif`,A0=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`,E0=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,T0=`uniform sampler2D t2D;
uniform float backgroundIntensity;
varying vec2 vUv;
void main() {
	vec4 texColor = texture2D( t2D, vUv );
	#ifdef DECODE_VIDEO_TEXTURE
		texColor = vec4( mix( pow( texColor.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), texColor.rgb * 0.0773993808, vec3( lessThanEqual( texColor.rgb, vec3( 0.04045 ) ) ) ), texColor.w );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,I0=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,R0=`uniform float backgroundBlurriness;
uniform float backgroundIntensity;
uniform mat3 backgroundRotation;
varying vec3 vWorldDirection;
#include <envmap_common_pars_fragment>
void main() {
	#ifdef ENVMAP_TYPE_PMREM
		vec4 texColor = textureLod( envMap, backgroundRotation * vWorldDirection, roughnessToMip( backgroundBlurriness ) );
	#else
		vec4 texColor = textureCube( envMap, backgroundRotation * vWorldDirection );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,C0=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,N0=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,P0=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
varying vec2 vHighPrecisionZW;
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vHighPrecisionZW = gl_Position.zw;
}`,L0=`#if DEPTH_PACKING == 3200
	uniform float opacity;
#endif
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
varying vec2 vHighPrecisionZW;
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#if DEPTH_PACKING == 3200
		diffuseColor.a = opacity;
	#endif
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <logdepthbuf_fragment>
	#ifdef USE_REVERSED_DEPTH_BUFFER
		float fragCoordZ = vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ];
	#else
		float fragCoordZ = 0.5 * vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ] + 0.5;
	#endif
	#if DEPTH_PACKING == 3200
		gl_FragColor = vec4( vec3( 1.0 - fragCoordZ ), opacity );
	#elif DEPTH_PACKING == 3201
		gl_FragColor = packDepthToRGBA( fragCoordZ );
	#elif DEPTH_PACKING == 3202
		gl_FragColor = vec4( packDepthToRGB( fragCoordZ ), 1.0 );
	#elif DEPTH_PACKING == 3203
		gl_FragColor = vec4( packDepthToRG( fragCoordZ ), 0.0, 1.0 );
	#endif
}`,D0=`#define DISTANCE
varying vec3 vWorldPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <worldpos_vertex>
	#include <clipping_planes_vertex>
	vWorldPosition = worldPosition.xyz;
}`,U0=`#define DISTANCE
uniform vec3 referencePosition;
uniform float nearDistance;
uniform float farDistance;
varying vec3 vWorldPosition;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	float dist = length( vWorldPosition - referencePosition );
	dist = ( dist - nearDistance ) / ( farDistance - nearDistance );
	dist = saturate( dist );
	gl_FragColor = vec4( dist, 0.0, 0.0, 1.0 );
}`,O0=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,F0=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,B0=`uniform float scale;
attribute float lineDistance;
varying float vLineDistance;
#include <common>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	vLineDistance = scale * lineDistance;
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,k0=`uniform vec3 diffuse;
uniform float opacity;
uniform float dashSize;
uniform float totalSize;
varying float vLineDistance;
#include <common>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	if ( mod( vLineDistance, totalSize ) > dashSize ) {
		discard;
	}
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,z0=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#if defined ( USE_ENVMAP ) || defined ( USE_SKINNING )
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinbase_vertex>
		#include <skinnormal_vertex>
		#include <defaultnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <fog_vertex>
}`,V0=`uniform vec3 diffuse;
uniform float opacity;
#ifndef FLAT_SHADED
	varying vec3 vNormal;
#endif
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		reflectedLight.indirectDiffuse += lightMapTexel.rgb * lightMapIntensity * RECIPROCAL_PI;
	#else
		reflectedLight.indirectDiffuse += vec3( 1.0 );
	#endif
	#include <aomap_fragment>
	reflectedLight.indirectDiffuse *= diffuseColor.rgb;
	vec3 outgoingLight = reflectedLight.indirectDiffuse;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,H0=`#define LAMBERT
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,G0=`#define LAMBERT
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_lambert_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_lambert_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,W0=`#define MATCAP
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <displacementmap_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
	vViewPosition = - mvPosition.xyz;
}`,j0=`#define MATCAP
uniform vec3 diffuse;
uniform float opacity;
uniform sampler2D matcap;
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	vec3 viewDir = normalize( vViewPosition );
	vec3 x = normalize( vec3( viewDir.z, 0.0, - viewDir.x ) );
	vec3 y = cross( viewDir, x );
	vec2 uv = vec2( dot( x, normal ), dot( y, normal ) ) * 0.495 + 0.5;
	#ifdef USE_MATCAP
		vec4 matcapColor = texture2D( matcap, uv );
	#else
		vec4 matcapColor = vec4( vec3( mix( 0.2, 0.8, uv.y ) ), 1.0 );
	#endif
	vec3 outgoingLight = diffuseColor.rgb * matcapColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,X0=`#define NORMAL
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	vViewPosition = - mvPosition.xyz;
#endif
}`,q0=`#define NORMAL
uniform float opacity;
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <uv_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 0.0, 0.0, 0.0, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	gl_FragColor = vec4( normalize( normal ) * 0.5 + 0.5, diffuseColor.a );
	#ifdef OPAQUE
		gl_FragColor.a = 1.0;
	#endif
}`,Y0=`#define PHONG
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,J0=`#define PHONG
uniform vec3 diffuse;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_phong_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_phong_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + reflectedLight.directSpecular + reflectedLight.indirectSpecular + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,K0=`#define STANDARD
varying vec3 vViewPosition;
#ifdef USE_TRANSMISSION
	varying vec3 vWorldPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
#ifdef USE_TRANSMISSION
	vWorldPosition = worldPosition.xyz;
#endif
}`,Z0=`#define STANDARD
#ifdef PHYSICAL
	#define IOR
	#define USE_SPECULAR
#endif
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float roughness;
uniform float metalness;
uniform float opacity;
#ifdef IOR
	uniform float ior;
#endif
#ifdef USE_SPECULAR
	uniform float specularIntensity;
	uniform vec3 specularColor;
	#ifdef USE_SPECULAR_COLORMAP
		uniform sampler2D specularColorMap;
	#endif
	#ifdef USE_SPECULAR_INTENSITYMAP
		uniform sampler2D specularIntensityMap;
	#endif
#endif
#ifdef USE_CLEARCOAT
	uniform float clearcoat;
	uniform float clearcoatRoughness;
#endif
#ifdef USE_DIFFUSE_ROUGHNESS
	uniform float diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		uniform sampler2D diffuseRoughnessMap;
	#endif
#endif
#ifdef USE_DISPERSION
	uniform float dispersion;
#endif
#ifdef USE_RETROREFLECTION
	uniform float retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	uniform float iridescence;
	uniform float iridescenceIOR;
	uniform float iridescenceThicknessMinimum;
	uniform float iridescenceThicknessMaximum;
#endif
#ifdef USE_SHEEN
	uniform vec3 sheenColor;
	uniform float sheenRoughness;
	#ifdef USE_SHEEN_COLORMAP
		uniform sampler2D sheenColorMap;
	#endif
	#ifdef USE_SHEEN_ROUGHNESSMAP
		uniform sampler2D sheenRoughnessMap;
	#endif
#endif
#ifdef USE_ANISOTROPY
	uniform vec2 anisotropyVector;
	#ifdef USE_ANISOTROPYMAP
		uniform sampler2D anisotropyMap;
	#endif
#endif
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <iridescence_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_physical_pars_fragment>
#include <transmission_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <clearcoat_pars_fragment>
#include <iridescence_pars_fragment>
#include <roughnessmap_pars_fragment>
#include <metalnessmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <roughnessmap_fragment>
	#include <metalnessmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <clearcoat_normal_fragment_begin>
	#include <clearcoat_normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_physical_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 totalDiffuse = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse;
	vec3 totalSpecular = reflectedLight.directSpecular + reflectedLight.indirectSpecular;
	#include <transmission_fragment>
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
	#ifdef USE_SHEEN
 
		outgoingLight = outgoingLight + sheenSpecularDirect + sheenSpecularIndirect;
 
 	#endif
	#ifdef USE_CLEARCOAT
		float dotNVcc = saturate( dot( geometryClearcoatNormal, geometryViewDir ) );
		vec3 Fcc = F_Schlick( material.clearcoatF0, material.clearcoatF90, dotNVcc );
		outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + clearcoatSpecularIndirect ) * material.clearcoat;
	#endif
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,Q0=`#define TOON
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,$0=`#define TOON
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <gradientmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_toon_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_toon_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,ty=`uniform float size;
uniform float scale;
#include <common>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
#ifdef USE_POINTS_UV
	varying vec2 vUv;
	uniform mat3 uvTransform;
#endif
void main() {
	#ifdef USE_POINTS_UV
		vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	#endif
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	gl_PointSize = size;
	#ifdef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) gl_PointSize *= ( scale / - mvPosition.z );
	#endif
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <fog_vertex>
}`,ey=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <color_pars_fragment>
#include <map_particle_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_particle_fragment>
	#include <color_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,ny=`#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <shadowmap_pars_vertex>
void main() {
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,iy=`uniform vec3 color;
uniform float opacity;
#include <common>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <logdepthbuf_pars_fragment>
#include <shadowmap_pars_fragment>
#include <shadowmask_pars_fragment>
void main() {
	#include <logdepthbuf_fragment>
	gl_FragColor = vec4( color, opacity * ( 1.0 - getShadowMask() ) );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,ay=`uniform float rotation;
uniform vec2 center;
#include <common>
#include <uv_pars_vertex>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	vec4 mvPosition = modelViewMatrix[ 3 ];
	vec2 scale = vec2( length( modelMatrix[ 0 ].xyz ), length( modelMatrix[ 1 ].xyz ) );
	#ifndef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) scale *= - mvPosition.z;
	#endif
	vec2 alignedPosition = ( position.xy - ( center - vec2( 0.5 ) ) ) * scale;
	vec2 rotatedPosition;
	rotatedPosition.x = cos( rotation ) * alignedPosition.x - sin( rotation ) * alignedPosition.y;
	rotatedPosition.y = sin( rotation ) * alignedPosition.x + cos( rotation ) * alignedPosition.y;
	mvPosition.xy += rotatedPosition;
	gl_Position = projectionMatrix * mvPosition;
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,sy=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,qt={alphahash_fragment:Tb,alphahash_pars_fragment:Ib,alphamap_fragment:Rb,alphamap_pars_fragment:Cb,alphatest_fragment:Nb,alphatest_pars_fragment:Pb,aomap_fragment:Lb,aomap_pars_fragment:Db,batching_pars_vertex:Ub,batching_vertex:Ob,begin_vertex:Fb,beginnormal_vertex:Bb,bsdfs:kb,iridescence_fragment:zb,bumpmap_pars_fragment:Vb,clipping_planes_fragment:Hb,clipping_planes_pars_fragment:Gb,clipping_planes_pars_vertex:Wb,clipping_planes_vertex:jb,color_fragment:Xb,color_pars_fragment:qb,color_pars_vertex:Yb,color_vertex:Jb,common:Kb,defaultnormal_vertex:Zb,displacementmap_pars_vertex:Qb,displacementmap_vertex:$b,emissivemap_fragment:tx,emissivemap_pars_fragment:ex,colorspace_fragment:nx,colorspace_pars_fragment:ix,envmap_fragment:ax,envmap_common_pars_fragment:sx,envmap_pars_fragment:rx,envmap_pars_vertex:ox,envmap_physical_pars_fragment:xx,envmap_vertex:cx,fog_vertex:lx,fog_pars_vertex:hx,fog_fragment:dx,fog_pars_fragment:ux,gradientmap_pars_fragment:fx,lightmap_pars_fragment:px,lights_lambert_fragment:mx,lights_lambert_pars_fragment:gx,lights_pars_begin:bx,lights_toon_fragment:yx,lights_toon_pars_fragment:_x,lights_phong_fragment:vx,lights_phong_pars_fragment:Mx,lights_physical_fragment:Sx,lights_physical_pars_fragment:wx,lights_fragment_begin:Ax,lights_fragment_maps:Ex,lights_fragment_end:Tx,lightprobes_pars_fragment:Ix,logdepthbuf_fragment:Rx,logdepthbuf_pars_fragment:Cx,logdepthbuf_pars_vertex:Nx,logdepthbuf_vertex:Px,map_fragment:Lx,map_pars_fragment:Dx,map_particle_fragment:Ux,map_particle_pars_fragment:Ox,metalnessmap_fragment:Fx,metalnessmap_pars_fragment:Bx,morphinstance_vertex:kx,morphcolor_vertex:zx,morphnormal_vertex:Vx,morphtarget_pars_vertex:Hx,morphtarget_vertex:Gx,normal_fragment_begin:Wx,normal_fragment_maps:jx,normal_pars_fragment:Xx,normal_pars_vertex:qx,normal_vertex:Yx,normalmap_pars_fragment:Jx,clearcoat_normal_fragment_begin:Kx,clearcoat_normal_fragment_maps:Zx,clearcoat_pars_fragment:Qx,iridescence_pars_fragment:$x,opaque_fragment:t0,packing:e0,premultiplied_alpha_fragment:n0,project_vertex:i0,dithering_fragment:a0,dithering_pars_fragment:s0,roughnessmap_fragment:r0,roughnessmap_pars_fragment:o0,shadowmap_pars_fragment:c0,shadowmap_pars_vertex:l0,shadowmap_vertex:h0,shadowmask_pars_fragment:d0,skinbase_vertex:u0,skinning_pars_vertex:f0,skinning_vertex:p0,skinnormal_vertex:m0,specularmap_fragment:g0,specularmap_pars_fragment:b0,tonemapping_fragment:x0,tonemapping_pars_fragment:y0,transmission_fragment:_0,transmission_pars_fragment:v0,uv_pars_fragment:M0,uv_pars_vertex:S0,uv_vertex:w0,worldpos_vertex:A0,background_vert:E0,background_frag:T0,backgroundCube_vert:I0,backgroundCube_frag:R0,cube_vert:C0,cube_frag:N0,depth_vert:P0,depth_frag:L0,distance_vert:D0,distance_frag:U0,equirect_vert:O0,equirect_frag:F0,linedashed_vert:B0,linedashed_frag:k0,meshbasic_vert:z0,meshbasic_frag:V0,meshlambert_vert:H0,meshlambert_frag:G0,meshmatcap_vert:W0,meshmatcap_frag:j0,meshnormal_vert:X0,meshnormal_frag:q0,meshphong_vert:Y0,meshphong_frag:J0,meshphysical_vert:K0,meshphysical_frag:Z0,meshtoon_vert:Q0,meshtoon_frag:$0,points_vert:ty,points_frag:ey,shadow_vert:ny,shadow_frag:iy,sprite_vert:ay,sprite_frag:sy},yt={common:{diffuse:{value:new jt(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new Vt},alphaMap:{value:null},alphaMapTransform:{value:new Vt},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new Vt}},envmap:{envMap:{value:null},envMapRotation:{value:new Vt},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new Vt}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new Vt}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new Vt},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new Vt},normalScale:{value:new Bt(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new Vt},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new Vt}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new Vt}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new Vt}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new jt(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new jt(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new Vt},alphaTest:{value:0},uvTransform:{value:new Vt}},sprite:{diffuse:{value:new jt(16777215)},opacity:{value:1},center:{value:new Bt(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new Vt},alphaMap:{value:null},alphaMapTransform:{value:new Vt},alphaTest:{value:0}}},xn={basic:{uniforms:sn([yt.common,yt.specularmap,yt.envmap,yt.aomap,yt.lightmap,yt.fog]),vertexShader:qt.meshbasic_vert,fragmentShader:qt.meshbasic_frag},lambert:{uniforms:sn([yt.common,yt.specularmap,yt.envmap,yt.aomap,yt.lightmap,yt.emissivemap,yt.bumpmap,yt.normalmap,yt.displacementmap,yt.fog,yt.lights,{emissive:{value:new jt(0)},envMapIntensity:{value:1}}]),vertexShader:qt.meshlambert_vert,fragmentShader:qt.meshlambert_frag},phong:{uniforms:sn([yt.common,yt.specularmap,yt.envmap,yt.aomap,yt.lightmap,yt.emissivemap,yt.bumpmap,yt.normalmap,yt.displacementmap,yt.fog,yt.lights,{emissive:{value:new jt(0)},specular:{value:new jt(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:qt.meshphong_vert,fragmentShader:qt.meshphong_frag},standard:{uniforms:sn([yt.common,yt.envmap,yt.aomap,yt.lightmap,yt.emissivemap,yt.bumpmap,yt.normalmap,yt.displacementmap,yt.roughnessmap,yt.metalnessmap,yt.fog,yt.lights,{emissive:{value:new jt(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:qt.meshphysical_vert,fragmentShader:qt.meshphysical_frag},toon:{uniforms:sn([yt.common,yt.aomap,yt.lightmap,yt.emissivemap,yt.bumpmap,yt.normalmap,yt.displacementmap,yt.gradientmap,yt.fog,yt.lights,{emissive:{value:new jt(0)}}]),vertexShader:qt.meshtoon_vert,fragmentShader:qt.meshtoon_frag},matcap:{uniforms:sn([yt.common,yt.bumpmap,yt.normalmap,yt.displacementmap,yt.fog,{matcap:{value:null}}]),vertexShader:qt.meshmatcap_vert,fragmentShader:qt.meshmatcap_frag},points:{uniforms:sn([yt.points,yt.fog]),vertexShader:qt.points_vert,fragmentShader:qt.points_frag},dashed:{uniforms:sn([yt.common,yt.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:qt.linedashed_vert,fragmentShader:qt.linedashed_frag},depth:{uniforms:sn([yt.common,yt.displacementmap]),vertexShader:qt.depth_vert,fragmentShader:qt.depth_frag},normal:{uniforms:sn([yt.common,yt.bumpmap,yt.normalmap,yt.displacementmap,{opacity:{value:1}}]),vertexShader:qt.meshnormal_vert,fragmentShader:qt.meshnormal_frag},sprite:{uniforms:sn([yt.sprite,yt.fog]),vertexShader:qt.sprite_vert,fragmentShader:qt.sprite_frag},background:{uniforms:{uvTransform:{value:new Vt},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:qt.background_vert,fragmentShader:qt.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new Vt}},vertexShader:qt.backgroundCube_vert,fragmentShader:qt.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:qt.cube_vert,fragmentShader:qt.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:qt.equirect_vert,fragmentShader:qt.equirect_frag},distance:{uniforms:sn([yt.common,yt.displacementmap,{referencePosition:{value:new z},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:qt.distance_vert,fragmentShader:qt.distance_frag},shadow:{uniforms:sn([yt.lights,yt.fog,{color:{value:new jt(0)},opacity:{value:1}}]),vertexShader:qt.shadow_vert,fragmentShader:qt.shadow_frag}};xn.physical={uniforms:sn([xn.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new Vt},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new Vt},clearcoatNormalScale:{value:new Bt(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new Vt},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new Vt},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new Vt},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new Vt},sheen:{value:0},sheenColor:{value:new jt(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new Vt},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new Vt},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new Vt},transmissionSamplerSize:{value:new Bt},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new Vt},attenuationDistance:{value:0},attenuationColor:{value:new jt(0)},specularColor:{value:new jt(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new Vt},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new Vt},anisotropyVector:{value:new Bt},anisotropyMap:{value:null},anisotropyMapTransform:{value:new Vt}}]),vertexShader:qt.meshphysical_vert,fragmentShader:qt.meshphysical_frag};tl={r:0,b:0,g:0},ry=new oe,hp=new Vt;hp.set(-1,0,0,0,1,0,0,0,1);Vr=class extends Nn{constructor(t=1,e={}){super(t,t,e),this.isWebGLCubeRenderTarget=!0;let n={width:t,height:t,depth:1},a=[n,n,n,n,n,n];this.texture=new cr(a),this._setTextureOptions(e),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(t,e){this.texture.type=e.type,this.texture.colorSpace=e.colorSpace,this.texture.generateMipmaps=e.generateMipmaps,this.texture.minFilter=e.minFilter,this.texture.magFilter=e.magFilter;let n={uniforms:{tEquirect:{value:null}},vertexShader:`

				varying vec3 vWorldDirection;

				vec3 transformDirection( in vec3 dir, in mat4 matrix ) {

					return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );

				}

				void main() {

					vWorldDirection = transformDirection( position, modelMatrix );

					#include <begin_vertex>
					#include <project_vertex>

				}
			`,fragmentShader:`

				uniform sampler2D tEquirect;

				varying vec3 vWorldDirection;

				#include <common>

				void main() {

					vec3 direction = normalize( vWorldDirection );

					vec2 sampleUV = equirectUv( direction );

					gl_FragColor = texture2D( tEquirect, sampleUV );

				}
			`},a=new as(5,5,5),s=new Bn({name:"CubemapFromEquirect",uniforms:Aa(n.uniforms),vertexShader:n.vertexShader,fragmentShader:n.fragmentShader,side:je,blending:ya});s.uniforms.tEquirect.value=e;let r=new nn(a,s),o=e.minFilter;return e.minFilter===Ni&&(e.minFilter=mn),new rs(1,10,this).update(t,r),e.minFilter=o,r.geometry.dispose(),r.material.dispose(),this}clear(t,e=!0,n=!0,a=!0){let s=t.getRenderTarget();for(let r=0;r<6;r++)t.setRenderTarget(this,r),t.clear(e,n,a);t.setRenderTarget(s)}},Hf=256,uy=3,fy=20,dp=256,up=16,py=3,my=new z,gy=new jt,nl=class i{constructor(t){this._renderer=t,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new rs(1,10,null),this._boxMesh=new nn(new as(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(t,e=0,n=.1,a=100,s={}){let{size:r=256,position:o=my}=s,c=this._renderer;this._setSize(r);let l=this._allocateTarget(),h=this._getSourceTarget(!0);e>0&&(h.texture.mipmapsAutoUpdate=!1);let u=c.autoClear,d=c.autoClearColor,f=c.autoClearDepth,x=c.autoClearStencil,v=t.background;c.autoClear=!0,c.autoClearColor=!0,c.autoClearDepth=!0,c.autoClearStencil=!0,v===null&&(t.background=c.getClearColor(gy));let m=new rs(n,a,h);return m.position.copy(o),m.update(c,t),c.autoClear=u,c.autoClearColor=d,c.autoClearDepth=f,c.autoClearStencil=x,t.background=v,e>0&&(h.texture.mipmapsAutoUpdate=!0,this._blur(l,e)),this._applyPMREM(l),l}fromEquirectangular(t,e=null){return this._fromTexture(t,e)}fromCubemap(t,e=null){return this._fromTexture(t,e)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=jf(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=Wf(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(t,e){return e>0?1-Math.sqrt(1-t/e):0}_setSize(t){this._cubeSize=Math.max(Hf,$h(t))}_fromTexture(t,e){t.mapping===va||t.mapping===hs?this._setSize(t.image.length===0?Hf:t.image[0].width||t.image[0].image.width):this._setSize(t.image.width/4);let n=e||this._allocateTarget();return this._textureToCubemap(t),this._applyPMREM(n),n}_allocateTarget(){let t=this._cubeSize,e=Gf(t,!1,!1),n=Math.log2(t)-uy;for(let a=0;a<=n;a++)e.texture.mipmaps.push({width:t>>a,height:t>>a});return e.texture.name="PMREM",e.texture.isPMREMTexture=!0,e}_getSourceTarget(t=!1){let e=this._cubeSize,n=this._sourceTarget;return(n===null||n.width!==e||t&&n.depthBuffer===!1)&&(n!==null&&n.dispose(),this._sourceTarget=Gf(e,!0,t)),this._sourceTarget}_compileMaterial(t){this._boxMesh.material=t,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(t,e,n){let a=this._boxMesh,s=this._cubeCamera;a.material=n,s.renderTarget=t,s.activeMipmapLevel=e;let r=t.width>>e;t.viewport.set(0,0,r,r),s.update(this._renderer,a),t.viewport.set(0,0,t.width,t.height)}_textureToCubemap(t){let e;t.mapping===va||t.mapping===hs?(this._cubemapMaterial===null&&(this._cubemapMaterial=jf()),e=this._cubemapMaterial,e.uniforms.flipEnvMap.value=t.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=Wf()),e=this._equirectMaterial),e.uniforms.envMap.value=t,this._renderCube(this._getSourceTarget(),0,e)}_applyPMREM(t){this._ggxMaterial===null&&(this._ggxMaterial=by(),this._integrationMaterial=xy());let e=this._cubeSize,n=t.texture.mipmaps.length-1,a=this._ggxMaterial.uniforms;a.envMap.value=this._sourceTarget.texture;let s=this._integrationMaterial.uniforms;s.envMap.value=this._sourceTarget.texture,s.sourceLod.value=Math.log2(e/up);for(let r=0;r<=n;r++){let o=i.lodToRoughness(r,n);if(r>n-py)s.roughness.value=o,this._renderCube(t,r,this._integrationMaterial);else{let c=o>0?Math.log2(e)+.5*Math.log2(6/(dp*Math.pow(o,4)))+.5:0;a.roughness.value=o,a.lodBias.value=c,this._renderCube(t,r,this._ggxMaterial)}}}_blur(t,e){this._blurMaterial===null&&(this._blurMaterial=yy());let n=this._blurMaterial,a=n.uniforms,s=this._sourceTarget;a.sigma.value=Math.min(e,Math.PI)/Math.SQRT2,a.envMap.value=s.texture,this._renderCube(t,0,n),a.envMap.value=t.texture,this._renderCube(s,0,n)}};Ty={[Uh]:"LINEAR_TONE_MAPPING",[Oh]:"REINHARD_TONE_MAPPING",[Fh]:"CINEON_TONE_MAPPING",[Bh]:"ACES_FILMIC_TONE_MAPPING",[zh]:"AGX_TONE_MAPPING",[Vh]:"NEUTRAL_TONE_MAPPING",[kh]:"CUSTOM_TONE_MAPPING"};fp=new wn,pp=new Ci(1,1),mp=new lr(1),gp=new tr,bp=new Yo,xp=new cr,Xf=[],qf=[],Yf=new Float32Array(16),Jf=new Float32Array(9),Kf=new Float32Array(4);pd=class{constructor(t,e,n){this.id=t,this.addr=n,this.cache=[],this.type=e.type,this.setValue=Yy(e.type)}},md=class{constructor(t,e,n){this.id=t,this.addr=n,this.cache=[],this.type=e.type,this.size=e.size,this.setValue=p_(e.type)}},gd=class{constructor(t){this.id=t,this.seq=[],this.map={}}setValue(t,e,n){let a=this.seq;for(let s=0,r=a.length;s!==r;++s){let o=a[s];o.setValue(t,e[o.id],n)}}},ud=/(\w+)(\])?(\[|\.)?/g;ps=class{constructor(t,e){this.seq=[],this.map={};let n=t.getProgramParameter(e,t.ACTIVE_UNIFORMS);for(let r=0;r<n;++r){let o=t.getActiveUniform(e,r),c=t.getUniformLocation(e,o.name);m_(o,c,this)}let a=[],s=[];for(let r of this.seq)r.type===t.SAMPLER_2D_SHADOW||r.type===t.SAMPLER_CUBE_SHADOW||r.type===t.SAMPLER_2D_ARRAY_SHADOW?a.push(r):s.push(r);a.length>0&&(this.seq=a.concat(s))}setValue(t,e,n,a){let s=this.map[e];s!==void 0&&s.setValue(t,n,a)}setOptional(t,e,n){let a=e[n];a!==void 0&&this.setValue(t,n,a)}static upload(t,e,n,a){for(let s=0,r=e.length;s!==r;++s){let o=e[s],c=n[o.id];c.needsUpdate!==!1&&o.setValue(t,c.value,a)}}static seqWithValue(t,e){let n=[];for(let a=0,s=t.length;a!==s;++a){let r=t[a];r.id in e&&n.push(r)}return n}};g_=37297,b_=0;$f=new Vt;v_={[Uh]:"Linear",[Oh]:"Reinhard",[Fh]:"Cineon",[Bh]:"ACESFilmic",[zh]:"AgX",[Vh]:"Neutral",[kh]:"Custom"};el=new z;T_=/^[ \t]*#include +<([\w\d./]+)>/gm;R_=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;N_={[Tr]:"SHADOWMAP_TYPE_PCF",[cs]:"SHADOWMAP_TYPE_VSM"};L_={[hs]:"ENVMAP_MODE_REFRACTION"};U_={[gc]:"ENVMAP_BLENDING_MULTIPLY",[wf]:"ENVMAP_BLENDING_MIX",[Af]:"ENVMAP_BLENDING_ADD"};B_=0,xd=class{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(t,e,n){let a=this._getShaderCacheForMaterial(t);return a.has(e)===!1&&(a.add(e),e.usedTimes++),a.has(n)===!1&&(a.add(n),n.usedTimes++),this}remove(t){let e=this.materialCache.get(t);for(let n of e)n.usedTimes--,n.usedTimes===0&&this.shaderCache.delete(n.code);return this.materialCache.delete(t),this}getVertexShaderStage(t){return this._getShaderStage(t.vertexShader)}getFragmentShaderStage(t){return this._getShaderStage(t.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(t){let e=this.materialCache,n=e.get(t);return n===void 0&&(n=new Set,e.set(t,n)),n}_getShaderStage(t){let e=this.shaderCache,n=e.get(t);return n===void 0&&(n=new yd(t),e.set(t,n)),n}},yd=class{constructor(t){this.id=B_++,this.code=t,this.usedTimes=0}};X_=0;K_=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,Z_=`uniform sampler2D shadow_pass;
uniform vec2 resolution;
uniform float radius;
void main() {
	const float samples = float( VSM_SAMPLES );
	float mean = 0.0;
	float squared_mean = 0.0;
	float uvStride = samples <= 1.0 ? 0.0 : 2.0 / ( samples - 1.0 );
	float uvStart = samples <= 1.0 ? 0.0 : - 1.0;
	for ( float i = 0.0; i < samples; i ++ ) {
		float uvOffset = uvStart + i * uvStride;
		#ifdef HORIZONTAL_PASS
			vec2 distribution = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( uvOffset, 0.0 ) * radius ) / resolution ).rg;
			mean += distribution.x;
			squared_mean += distribution.y * distribution.y + distribution.x * distribution.x;
		#else
			float depth = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( 0.0, uvOffset ) * radius ) / resolution ).r;
			mean += depth;
			squared_mean += depth * depth;
		#endif
	}
	mean = mean / samples;
	squared_mean = squared_mean / samples;
	float std_dev = sqrt( max( 0.0, squared_mean - mean * mean ) );
	gl_FragColor = vec4( mean, std_dev, 0.0, 1.0 );
}`,Q_=[new z(1,0,0),new z(-1,0,0),new z(0,1,0),new z(0,-1,0),new z(0,0,1),new z(0,0,-1)],$_=[new z(0,-1,0),new z(0,-1,0),new z(0,0,1),new z(0,0,-1),new z(0,-1,0),new z(0,-1,0)],cp=new oe,kr=new z,fd=new z;av=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,sv=`
uniform sampler2DArray depthColor;
uniform float depthWidth;
uniform float depthHeight;

void main() {

	vec2 coord = vec2( gl_FragCoord.x / depthWidth, gl_FragCoord.y / depthHeight );

	if ( coord.x >= 1.0 ) {

		gl_FragDepth = texture( depthColor, vec3( coord.x - 1.0, coord.y, 1 ) ).r;

	} else {

		gl_FragDepth = texture( depthColor, vec3( coord.x, coord.y, 0 ) ).r;

	}

}`,_d=class{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(t,e){if(this.texture===null){let n=new hr(t.texture);(t.depthNear!==e.depthNear||t.depthFar!==e.depthFar)&&(this.depthNear=t.depthNear,this.depthFar=t.depthFar),this.texture=n}}getMesh(t){if(this.texture!==null&&this.mesh===null){let e=t.cameras[0].viewport,n=new Bn({vertexShader:av,fragmentShader:sv,uniforms:{depthColor:{value:this.texture},depthWidth:{value:e.z},depthHeight:{value:e.w}}});this.mesh=new nn(new ur(20,20),n)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}},vd=class extends Yn{constructor(t,e){super();let n=this,a=null,s=1,r=null,o="local-floor",c=1,l=null,h=null,u=null,d=null,f=null,x=null,v=typeof XRWebGLBinding<"u",m=new _d,g={},y=e.getContextAttributes(),w=null,p=null,_=[],S=[],b=new Bt,M=null,E=null,A=new fn;A.viewport=new ce;let I=new fn;I.viewport=new ce;let N=[A,I],L=new fc,P=null,U=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(Y){let ct=_[Y];return ct===void 0&&(ct=new es,_[Y]=ct),ct.getTargetRaySpace()},this.getControllerGrip=function(Y){let ct=_[Y];return ct===void 0&&(ct=new es,_[Y]=ct),ct.getGripSpace()},this.getHand=function(Y){let ct=_[Y];return ct===void 0&&(ct=new es,_[Y]=ct),ct.getHandSpace()};function V(Y){let ct=S.indexOf(Y.inputSource);if(ct===-1)return;let mt=_[ct];mt!==void 0&&(mt.update(Y.inputSource,Y.frame,l||r),mt.dispatchEvent({type:Y.type,data:Y.inputSource}))}function O(){a.removeEventListener("select",V),a.removeEventListener("selectstart",V),a.removeEventListener("selectend",V),a.removeEventListener("squeeze",V),a.removeEventListener("squeezestart",V),a.removeEventListener("squeezeend",V),a.removeEventListener("end",O),a.removeEventListener("inputsourceschange",Q);for(let Y=0;Y<_.length;Y++){let ct=S[Y];ct!==null&&(S[Y]=null,_[Y].disconnect(ct))}P=null,U=null,m.reset();for(let Y in g)delete g[Y];if(t.setRenderTarget(w),f=null,d=null,u=null,a=null,p=null,Pt.stop(),n.isPresenting=!1,t.setPixelRatio(M),t.setSize(b.width,b.height,!1),E!==null){let Y=E.camera;Y.fov=E.fov,Y.zoom=E.zoom,Y.updateProjectionMatrix(),E=null}n.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(Y){s=Y,n.isPresenting===!0&&Ft("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(Y){o=Y,n.isPresenting===!0&&Ft("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return l||r},this.setReferenceSpace=function(Y){l=Y},this.getBaseLayer=function(){return d!==null?d:f},this.getBinding=function(){return u===null&&v&&(u=new XRWebGLBinding(a,e)),u},this.getFrame=function(){return x},this.getSession=function(){return a},this.setSession=async function(Y){if(a=Y,a!==null){if(w=t.getRenderTarget(),a.addEventListener("select",V),a.addEventListener("selectstart",V),a.addEventListener("selectend",V),a.addEventListener("squeeze",V),a.addEventListener("squeezestart",V),a.addEventListener("squeezeend",V),a.addEventListener("end",O),a.addEventListener("inputsourceschange",Q),y.xrCompatible!==!0&&await e.makeXRCompatible(),M=t.getPixelRatio(),t.getSize(b),v&&"createProjectionLayer"in XRWebGLBinding.prototype){let mt=null,Tt=null,gt=null;y.depth&&(gt=y.stencil?e.DEPTH24_STENCIL8:e.DEPTH_COMPONENT24,mt=y.stencil?Pi:Ti,Tt=y.stencil?Ma:An);let Ot={colorFormat:e.RGBA8,depthFormat:gt,scaleFactor:s};u=this.getBinding(),d=u.createProjectionLayer(Ot),a.updateRenderState({layers:[d]}),t.setPixelRatio(1),t.setSize(d.textureWidth,d.textureHeight,!1),p=new Nn(d.textureWidth,d.textureHeight,{format:bn,type:an,depthTexture:new Ci(d.textureWidth,d.textureHeight,Tt,void 0,void 0,void 0,void 0,void 0,void 0,mt),stencilBuffer:y.stencil,colorSpace:t.outputColorSpace,samples:y.antialias?4:0,resolveDepthBuffer:d.ignoreDepthValues===!1,resolveStencilBuffer:d.ignoreDepthValues===!1,storeMultisampledDepthBuffer:d.ignoreDepthValues===!1,storeMultisampledStencilBuffer:d.ignoreDepthValues===!1})}else{let mt={antialias:y.antialias,alpha:!0,depth:y.depth,stencil:y.stencil,framebufferScaleFactor:s};f=new XRWebGLLayer(a,e,mt),a.updateRenderState({baseLayer:f}),t.setPixelRatio(1),t.setSize(f.framebufferWidth,f.framebufferHeight,!1),p=new Nn(f.framebufferWidth,f.framebufferHeight,{format:bn,type:an,colorSpace:t.outputColorSpace,stencilBuffer:y.stencil,resolveDepthBuffer:f.ignoreDepthValues===!1,resolveStencilBuffer:f.ignoreDepthValues===!1,storeMultisampledDepthBuffer:f.ignoreDepthValues===!1,storeMultisampledStencilBuffer:f.ignoreDepthValues===!1})}p.isXRRenderTarget=!0,this.setFoveation(c),l=null,r=await a.requestReferenceSpace(o),Pt.setContext(a),Pt.start(),n.isPresenting=!0,n.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(a!==null)return a.environmentBlendMode},this.getDepthTexture=function(){return m.getDepthTexture()};function Q(Y){for(let ct=0;ct<Y.removed.length;ct++){let mt=Y.removed[ct],Tt=S.indexOf(mt);Tt>=0&&(S[Tt]=null,_[Tt].disconnect(mt))}for(let ct=0;ct<Y.added.length;ct++){let mt=Y.added[ct],Tt=S.indexOf(mt);if(Tt===-1){for(let Ot=0;Ot<_.length;Ot++)if(Ot>=S.length){S.push(mt),Tt=Ot;break}else if(S[Ot]===null){S[Ot]=mt,Tt=Ot;break}if(Tt===-1)break}let gt=_[Tt];gt&&gt.connect(mt)}}function G(Y,ct){ct===null?Y.matrixWorld.copy(Y.matrix):Y.matrixWorld.multiplyMatrices(ct.matrixWorld,Y.matrix),Y.matrixWorldInverse.copy(Y.matrixWorld).invert()}this.updateCamera=function(Y){if(a===null)return;let ct=Y.near,mt=Y.far;m.texture!==null&&(m.depthNear>0&&(ct=m.depthNear),m.depthFar>0&&(mt=m.depthFar)),L.near=I.near=A.near=ct,L.far=I.far=A.far=mt,(P!==L.near||U!==L.far)&&(a.updateRenderState({depthNear:L.near,depthFar:L.far}),P=L.near,U=L.far),L.layers.mask=Y.layers.mask|6,A.layers.mask=L.layers.mask&-5,I.layers.mask=L.layers.mask&-3;let Tt=Y.parent,gt=L.cameras;G(L,Tt);for(let Ot=0;Ot<gt.length;Ot++)G(gt[Ot],Tt);L.projectionMatrix.copy(A.projectionMatrix),L.projectionMatrixInverse.copy(A.projectionMatrixInverse),E===null&&Y.isPerspectiveCamera&&(E={camera:Y,fov:Y.fov,zoom:Y.zoom}),Z(Y,L,Tt)};function Z(Y,ct,mt){mt===null?Y.matrix.copy(ct.matrixWorld):(Y.matrix.copy(mt.matrixWorld),Y.matrix.invert(),Y.matrix.multiply(ct.matrixWorld)),Y.matrix.decompose(Y.position,Y.quaternion,Y.scale),Y.updateMatrixWorld(!0),Y.projectionMatrix.copy(ct.projectionMatrix),Y.projectionMatrixInverse.copy(ct.projectionMatrixInverse),Y.isPerspectiveCamera&&(Y.fov=Qa*2*Math.atan(1/Y.projectionMatrix.elements[5]),Y.zoom=1)}this.getCamera=function(){return L},this.getFoveation=function(){if(!(d===null&&f===null))return c},this.setFoveation=function(Y){c=Y,d!==null&&(d.fixedFoveation=Y),f!==null&&f.fixedFoveation!==void 0&&(f.fixedFoveation=Y)},this.hasDepthSensing=function(){return m.texture!==null},this.getDepthSensingMesh=function(){return m.getMesh(L)},this.getCameraTexture=function(Y){return g[Y]};let et=null;function ht(Y,ct){if(h=ct.getViewerPose(l||r),x=ct,h!==null){let mt=h.views;f!==null&&(t.setRenderTargetFramebuffer(p,f.framebuffer),t.setRenderTarget(p));let Tt=!1;mt.length!==L.cameras.length&&(L.cameras.length=0,Tt=!0);for(let Dt=0;Dt<mt.length;Dt++){let kt=mt[Dt],Yt=null;if(f!==null)Yt=f.getViewport(kt);else{let Ae=u.getViewSubImage(d,kt);Yt=Ae.viewport,Dt===0&&(t.setRenderTargetTextures(p,Ae.colorTexture,Ae.depthStencilTexture),t.setRenderTarget(p))}let Xt=N[Dt];Xt===void 0&&(Xt=new fn,Xt.layers.enable(Dt),Xt.viewport=new ce,N[Dt]=Xt),Xt.matrix.fromArray(kt.transform.matrix),Xt.matrix.decompose(Xt.position,Xt.quaternion,Xt.scale),Xt.projectionMatrix.fromArray(kt.projectionMatrix),Xt.projectionMatrixInverse.copy(Xt.projectionMatrix).invert(),Xt.viewport.set(Yt.x,Yt.y,Yt.width,Yt.height),Dt===0&&(L.matrix.copy(Xt.matrix),L.matrix.decompose(L.position,L.quaternion,L.scale)),Tt===!0&&L.cameras.push(Xt)}let gt=a.enabledFeatures;if(gt&&gt.includes("depth-sensing")&&a.depthUsage=="gpu-optimized"&&v){u=n.getBinding();let Dt=u.getDepthInformation(mt[0]);Dt&&Dt.isValid&&Dt.texture&&m.init(Dt,a.renderState)}if(gt&&gt.includes("camera-access")&&v){t.state.unbindTexture(),u=n.getBinding();for(let Dt=0;Dt<mt.length;Dt++){let kt=mt[Dt].camera;if(kt){let Yt=g[kt];Yt||(Yt=new hr,g[kt]=Yt);let Xt=u.getCameraImage(kt);Yt.sourceTexture=Xt}}}}for(let mt=0;mt<_.length;mt++){let Tt=S[mt],gt=_[mt];Tt!==null&&gt!==void 0&&gt.update(Tt,ct,l||r)}et&&et(Y,ct),ct.detectedPlanes&&n.dispatchEvent({type:"planesdetected",data:ct}),x=null}let Pt=new lp;Pt.setAnimationLoop(ht),this.setAnimationLoop=function(Y){et=Y},this.dispose=function(){}}},rv=new oe,yp=new Vt;yp.set(-1,0,0,0,1,0,0,0,1);lv=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]),di=null;il=class{constructor(t={}){let{canvas:e=Uf(),context:n=null,depth:a=!0,stencil:s=!1,alpha:r=!1,antialias:o=!1,premultipliedAlpha:c=!0,preserveDrawingBuffer:l=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:u=!1,reversedDepthBuffer:d=!1,outputBufferType:f=an}=t;this.isWebGLRenderer=!0;let x;if(n!==null){if(typeof WebGLRenderingContext<"u"&&n instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");x=n.getContextAttributes().alpha}else x=r;let v=f,m=new Set([fs,us,Sa]),g=new Set([an,An,Yi,Ma,_c,vc]),y=new Uint32Array(4),w=new Int32Array(4),p={textures:[],min:[],max:[],resolution:[]},_=null,S=null,b=[],M=[],E=null;this.domElement=e,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=li,this.toneMappingExposure=1,this.transmissionResolutionScale=1;let A=this,I=!1,N=null,L=null,P=null,U=null;this._outputColorSpace=Rn;let V=0,O=0,Q=null,G=-1,Z=null,et=new ce,ht=new ce,Pt=null,Y=new jt(0),ct=0,mt=e.width,Tt=e.height,gt=1,Ot=null,ge=null,Dt=new ce(0,0,mt,Tt),kt=new ce(0,0,mt,Tt),Yt=!1,Xt=new Ri,Ae=new ar,nt=!1,St=!1,wt=new oe,Qt=new z,Ht=new ce,be={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0},fe=!1;function ne(){return Q===null?gt:1}let B=n;function Ee(C,F){return e.getContext(C,F)}let $t,Jt,dt,se,At,Lt,D,T,W,at,tt,lt,ut,$,J,ft,R,k,H,j,it,st,_t;try{let C={alpha:!0,depth:a,stencil:s,antialias:o,premultipliedAlpha:c,preserveDrawingBuffer:l,powerPreference:h,failIfMajorPerformanceCaveat:u};if("setAttribute"in e&&e.setAttribute("data-engine",`three.js r${"187"}`),e.addEventListener("webglcontextlost",vt,!1),e.addEventListener("webglcontextrestored",Ut,!1),e.addEventListener("webglcontextcreationerror",pt,!1),B===null){let F="webgl2";if(B=Ee(F,C),B===null)throw Ee(F)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}Ct()}catch(C){throw e.removeEventListener("webglcontextlost",vt,!1),e.removeEventListener("webglcontextrestored",Ut,!1),e.removeEventListener("webglcontextcreationerror",pt,!1),zt("WebGLRenderer: "+C.message),C}function Ct(){$t=new vy(B),$t.init(),it=new iv(B,$t),Jt=new hy(B,$t,t,it),dt=new ev(B,$t),Jt.reversedDepthBuffer&&d&&dt.buffers.depth.setReversed(!0),L=B.createFramebuffer(),P=B.createFramebuffer(),U=B.createFramebuffer(),se=new wy(B),At=new V_,Lt=new nv(B,$t,dt,At,Jt,it,se),D=new _y(A),T=new Eb(B),st=new cy(B,T),W=new My(B,T,se,st),at=new Ey(B,W,T,st,se),k=new Ay(B,Jt,Lt),J=new dy(At),tt=new z_(A,D,$t,Jt,st,J),lt=new ov(A,At),ut=new G_,$=new J_($t),R=new oy(A,D,dt,at,x,c),ft=new tv(A,at,Jt),_t=new cv(B,se,Jt,dt),H=new ly(B,$t,se),j=new Sy(B,$t,se),se.programs=tt.programs,A.capabilities=Jt,A.extensions=$t,A.properties=At,A.renderLists=ut,A.shadowMap=ft,A.state=dt,A.info=se}v!==an&&(E=new Iy(v,e.width,e.height,o,a,s));let ot=new vd(A,B);this.xr=ot,this.getContext=function(){return B},this.getContextAttributes=function(){return B.getContextAttributes()},this.forceContextLoss=function(){let C=$t.get("WEBGL_lose_context");C&&C.loseContext()},this.forceContextRestore=function(){let C=$t.get("WEBGL_lose_context");C&&C.restoreContext()},this.getPixelRatio=function(){return gt},this.setPixelRatio=function(C){C!==void 0&&(gt=C,this.setSize(mt,Tt,!1))},this.getSize=function(C){return C.set(mt,Tt)},this.setSize=function(C,F,K=!0){if(ot.isPresenting){Ft("WebGLRenderer: Can't change size while VR device is presenting.");return}mt=C,Tt=F,e.width=Math.floor(C*gt),e.height=Math.floor(F*gt),K===!0&&(e.style.width=C+"px",e.style.height=F+"px"),E!==null&&E.setSize(e.width,e.height),this.setViewport(0,0,C,F)},this.getDrawingBufferSize=function(C){return C.set(mt*gt,Tt*gt).floor()},this.setDrawingBufferSize=function(C,F,K){mt=C,Tt=F,gt=K,e.width=Math.floor(C*K),e.height=Math.floor(F*K),this.setViewport(0,0,C,F)},this.setEffects=function(C){if(v===an){zt("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(C){for(let F=0;F<C.length;F++)if(C[F].isOutputPass===!0){Ft("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}E.setEffects(C||[])},this.getCurrentViewport=function(C){return C.copy(et)},this.getViewport=function(C){return C.copy(Dt)},this.setViewport=function(C,F,K,X){C.isVector4?Dt.set(C.x,C.y,C.z,C.w):Dt.set(C,F,K,X),dt.viewport(et.copy(Dt).multiplyScalar(ne()).round())},this.getScissor=function(C){return C.copy(kt)},this.setScissor=function(C,F,K,X){C.isVector4?kt.set(C.x,C.y,C.z,C.w):kt.set(C,F,K,X),dt.scissor(ht.copy(kt).multiplyScalar(ne()).round())},this.getScissorTest=function(){return Yt},this.setScissorTest=function(C){dt.setScissorTest(Yt=C)},this.setOpaqueSort=function(C){Ot=C},this.setTransparentSort=function(C){ge=C},this.getClearColor=function(C){return C.copy(R.getClearColor())},this.setClearColor=function(){R.setClearColor(...arguments)},this.getClearAlpha=function(){return R.getClearAlpha()},this.setClearAlpha=function(){R.setClearAlpha(...arguments)},this.clear=function(C=!0,F=!0,K=!0){let X=0;if(C){let q=!1;if(Q!==null){let xt=Q.texture.format;q=m.has(xt)}if(q){let xt=Q.texture.type,Et=g.has(xt),bt=R.getClearColor(),Mt=R.getClearAlpha(),Nt=bt.r,Gt=bt.g,te=bt.b;Et?(y[0]=Nt,y[1]=Gt,y[2]=te,y[3]=Mt,B.clearBufferuiv(B.COLOR,0,y)):(w[0]=Nt,w[1]=Gt,w[2]=te,w[3]=Mt,B.clearBufferiv(B.COLOR,0,w))}else X|=B.COLOR_BUFFER_BIT}F&&(X|=B.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),K&&(X|=B.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),X!==0&&B.clear(X)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(C){C.setRenderer(this),N=C},this.dispose=function(){e.removeEventListener("webglcontextlost",vt,!1),e.removeEventListener("webglcontextrestored",Ut,!1),e.removeEventListener("webglcontextcreationerror",pt,!1),R.dispose(),ut.dispose(),$.dispose(),Lt.dispose(),At.dispose(),D.dispose(),at.dispose(),W.dispose(),st.dispose(),_t.dispose(),tt.dispose(),ot.dispose(),ot.removeEventListener("sessionstart",cu),ot.removeEventListener("sessionend",lu),oa.stop()};function vt(C){C.preventDefault(),$s("WebGLRenderer: Context Lost."),I=!0}function Ut(){$s("WebGLRenderer: Context Restored."),I=!1;let C=se.autoReset,F=ft.enabled,K=ft.autoUpdate,X=ft.needsUpdate,q=ft.type;Ct(),se.autoReset=C,ft.enabled=F,ft.autoUpdate=K,ft.needsUpdate=X,ft.type=q}function pt(C){zt("WebGLRenderer: A WebGL context could not be created. Reason: ",C.statusMessage)}function re(C){let F=C.target;F.removeEventListener("dispose",re),Te(F)}function Te(C){Gn(C),At.remove(C)}function Gn(C){let F=At.get(C).programs;F!==void 0&&(F.forEach(function(K){tt.releaseProgram(K)}),C.isShaderMaterial&&tt.releaseShaderCache(C))}this.renderBufferDirect=function(C,F,K,X,q,xt){F===null&&(F=be);let Et=q.isMesh&&q.matrixWorld.determinantAffine()<0,bt=mg(C,F,K,X,q);dt.setMaterial(X,Et);let Mt=K.index,Nt=1;if(X.wireframe===!0){if(Mt=W.getWireframeAttribute(K),Mt===void 0)return;Nt=2}let Gt=K.drawRange,te=K.attributes.position,It=Gt.start*Nt,ee=(Gt.start+Gt.count)*Nt;xt!==null&&(It=Math.max(It,xt.start*Nt),ee=Math.min(ee,(xt.start+xt.count)*Nt)),Mt!==null?(It=Math.max(It,0),ee=Math.min(ee,Mt.count)):te!=null&&(It=Math.max(It,0),ee=Math.min(ee,te.count));let Pe=ee-It;if(Pe<0||Pe===1/0)return;st.setup(q,X,bt,K,Mt);let Se,_e=H;if(Mt!==null&&(Se=T.get(Mt),_e=j,_e.setIndex(Se)),q.isMesh)X.wireframe===!0?(dt.setLineWidth(X.wireframeLinewidth*ne()),_e.setMode(B.LINES)):_e.setMode(B.TRIANGLES);else if(q.isLine){let Ze=X.linewidth;Ze===void 0&&(Ze=1),dt.setLineWidth(Ze*ne()),q.isLineSegments?_e.setMode(B.LINES):q.isLineLoop?_e.setMode(B.LINE_LOOP):_e.setMode(B.LINE_STRIP)}else q.isPoints?_e.setMode(B.POINTS):q.isSprite&&_e.setMode(B.TRIANGLES);if(q.isBatchedMesh)if($t.get("WEBGL_multi_draw"))_e.renderMultiDraw(q._multiDrawStarts,q._multiDrawCounts,q._multiDrawCount);else{let Ze=q._multiDrawStarts,Rt=q._multiDrawCounts,hn=q._multiDrawCount,le=Mt?T.get(Mt).bytesPerElement:1,ca=At.get(X).currentProgram.getUniforms();for(let Qe=0;Qe<hn;Qe++)ca.setValue(B,"_gl_DrawID",Qe),_e.render(Ze[Qe]/le,Rt[Qe])}else if(q.isInstancedMesh)_e.renderInstances(It,Pe,q.count);else if(K.isInstancedBufferGeometry){let Ze=K._maxInstanceCount!==void 0?K._maxInstanceCount:1/0,Rt=Math.min(K.instanceCount,Ze);_e.renderInstances(It,Pe,Rt)}else _e.render(It,Pe)};function Na(C,F,K,X){N!==null&&C.isNodeMaterial&&N.setObject(X,C),nt===!0&&J.setState(C,K,!1),C.transparent===!0&&C.side===kn&&C.forceSinglePass===!1?(C.side=je,C.needsUpdate=!0,zs(C,F,X),C.side=ci,C.needsUpdate=!0,zs(C,F,X),C.side=kn):zs(C,F,X)}this.compile=function(C,F,K=null){K===null&&(K=C),N!==null&&N.renderStart(C,F,K),S=$.get(K),S.init(F),M.push(S),K.traverseVisible(function(q){q.isLight&&q.layers.test(F.layers)&&(S.pushLight(q),q.castShadow&&S.pushShadow(q))}),C!==K&&C.traverseVisible(function(q){q.isLight&&q.layers.test(F.layers)&&(S.pushLight(q),q.castShadow&&S.pushShadow(q))}),S.setupLights(),N!==null&&N.updateLights(S.state.lightsArray),St=this.localClippingEnabled,nt=J.init(this.clippingPlanes,St),nt===!0&&J.setGlobalState(this.clippingPlanes,F),N!==null&&ft.render(S.state.shadowsArray,K,F);let X=new Set;return C.traverse(function(q){if(!(q.isMesh||q.isPoints||q.isLine||q.isSprite))return;let xt=q.material;if(xt)if(Array.isArray(xt))for(let Et=0;Et<xt.length;Et++){let bt=xt[Et];Na(bt,K,F,q),X.add(bt)}else Na(xt,K,F,q),X.add(xt)}),S=M.pop(),N!==null&&N.renderEnd(),X},this.compileAsync=function(C,F,K=null){let X=this.compile(C,F,K);return new Promise(q=>{function xt(){if(X.forEach(function(Et){let Mt=At.get(Et).currentProgram;(Mt===void 0||Mt.isReady())&&X.delete(Et)}),X.size===0){q(C);return}setTimeout(xt,10)}$t.get("KHR_parallel_shader_compile")!==null?xt():setTimeout(xt,10)})};let jl=null;function fg(C){jl&&jl(C)}function cu(){oa.stop()}function lu(){oa.start()}let oa=new lp;oa.setAnimationLoop(fg),typeof self<"u"&&oa.setContext(self),this.setAnimationLoop=function(C){jl=C,ot.setAnimationLoop(C),C===null?oa.stop():oa.start()},ot.addEventListener("sessionstart",cu),ot.addEventListener("sessionend",lu),this.render=function(C,F){if(F!==void 0&&F.isCamera!==!0){zt("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(I===!0)return;N!==null&&N.renderStart(C,F);let K=ot.enabled===!0&&ot.isPresenting===!0,X=E!==null&&(Q===null||K)&&E.begin(A,Q);if(C.matrixWorldAutoUpdate===!0&&C.updateMatrixWorld(),F.parent===null&&F.matrixWorldAutoUpdate===!0&&F.updateMatrixWorld(),ot.enabled===!0&&ot.isPresenting===!0&&(E===null||E.isCompositing()===!1)&&(ot.cameraAutoUpdate===!0&&ot.updateCamera(F),F=ot.getCamera()),C.isScene===!0&&C.onBeforeRender(A,C,F,Q),S=$.get(C,M.length),S.init(F),S.state.textureUnits=Lt.getTextureUnits(),M.push(S),wt.multiplyMatrices(F.projectionMatrix,F.matrixWorldInverse),F.isArrayCamera?Ae.setFromArrayCamera(F):Xt.setFromProjectionMatrix(wt,Fn,F.reversedDepth),St=this.localClippingEnabled,nt=J.init(this.clippingPlanes,St),_=ut.get(C,b.length),_.init(),b.push(_),this.info.render.frame++,ot.enabled===!0&&ot.isPresenting===!0){let Et=A.xr.getDepthSensingMesh();Et!==null&&Xl(Et,F,-1/0,A.sortObjects)}Xl(C,F,0,A.sortObjects),_.finish(),N!==null&&N.updateLights(S.state.lightsArray),A.sortObjects===!0&&_.sort(Ot,ge),fe=ot.enabled===!1||ot.isPresenting===!1||ot.hasDepthSensing()===!1,fe&&R.addToRenderList(_,C),this.info.autoReset===!0&&this.info.reset(),nt===!0&&J.beginShadows();let q=S.state.shadowsArray;if(ft.render(q,C,F),nt===!0&&J.endShadows(),(X&&E.hasRenderPass())===!1){let Et=_.opaque,bt=_.transmissive;if(S.setupLights(),F.isArrayCamera){let Mt=F.cameras;if(bt.length>0)for(let Nt=0,Gt=Mt.length;Nt<Gt;Nt++){let te=Mt[Nt];du(Et,bt,C,te)}fe&&R.render(C);for(let Nt=0,Gt=Mt.length;Nt<Gt;Nt++){let te=Mt[Nt];hu(_,C,te,te.viewport)}}else bt.length>0&&du(Et,bt,C,F),fe&&R.render(C),hu(_,C,F)}Q!==null&&O===0&&(Lt.updateMultisampleRenderTarget(Q),Lt.updateRenderTargetMipmap(Q)),X&&E.end(A),C.isScene===!0&&C.onAfterRender(A,C,F),st.resetDefaultState(),G=-1,Z=null,M.pop(),M.length>0?(S=M[M.length-1],Lt.setTextureUnits(S.state.textureUnits),nt===!0&&J.setGlobalState(A.clippingPlanes,S.state.camera)):S=null,b.pop(),b.length>0?_=b[b.length-1]:_=null,N!==null&&N.renderEnd()};function Xl(C,F,K,X){if(C.visible===!1)return;if(C.layers.test(F.layers)){if(C.isGroup)K=C.renderOrder;else if(C.isLOD)C.autoUpdate===!0&&C.update(F);else if(C.isLight)S.pushLight(C),C.castShadow&&S.pushShadow(C);else if(C.isSprite){let Et=F.isArrayCamera?Ae:Xt;if(!C.frustumCulled||C.intersectsFrustum(Et)){X&&Ht.setFromMatrixPosition(C.matrixWorld).applyMatrix4(wt);let bt=at.update(C),Mt=C.material;Mt.visible&&_.push(C,bt,Mt,K,Ht.z,null,F)}}else if(C.isMesh||C.isLine||C.isPoints){let Et=F.isArrayCamera?Ae:Xt;if(!C.frustumCulled||C.intersectsFrustum(Et)){let bt=at.update(C),Mt=C.material;if(X&&(C.boundingSphere!==void 0?(C.boundingSphere===null&&C.computeBoundingSphere(),Ht.copy(C.boundingSphere.center)):(bt.boundingSphere===null&&bt.computeBoundingSphere(),Ht.copy(bt.boundingSphere.center)),Ht.applyMatrix4(C.matrixWorld).applyMatrix4(wt)),Array.isArray(Mt)){let Nt=bt.groups;for(let Gt=0,te=Nt.length;Gt<te;Gt++){let It=Nt[Gt],ee=Mt[It.materialIndex];ee&&ee.visible&&_.push(C,bt,ee,K,Ht.z,It,F)}}else Mt.visible&&_.push(C,bt,Mt,K,Ht.z,null,F)}}}let xt=C.children;for(let Et=0,bt=xt.length;Et<bt;Et++)Xl(xt[Et],F,K,X)}function hu(C,F,K,X){let{opaque:q,transmissive:xt,transparent:Et}=C;S.setupLightsView(K),nt===!0&&J.setGlobalState(A.clippingPlanes,K),X&&dt.viewport(et.copy(X)),q.length>0&&ao(q,F,K),xt.length>0&&ao(xt,F,K),Et.length>0&&ao(Et,F,K),dt.buffers.depth.setTest(!0),dt.buffers.depth.setMask(!0),dt.buffers.color.setMask(!0),dt.setPolygonOffset(!1)}function du(C,F,K,X){if((K.isScene===!0?K.overrideMaterial:null)!==null)return;if(S.state.transmissionRenderTarget[X.id]===void 0){let It=$t.has("EXT_color_buffer_half_float")||$t.has("EXT_color_buffer_float");S.state.transmissionRenderTarget[X.id]=new Nn(1,1,{generateMipmaps:!0,type:It?Zn:an,minFilter:Ni,samples:Math.max(4,Jt.samples),stencilBuffer:s,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:Kt.workingColorSpace})}let xt=S.state.transmissionRenderTarget[X.id],Et=X.viewport||et;xt.setSize(Et.z*A.transmissionResolutionScale,Et.w*A.transmissionResolutionScale);let bt=A.getRenderTarget(),Mt=A.getActiveCubeFace(),Nt=A.getActiveMipmapLevel();A.setRenderTarget(xt),A.getClearColor(Y),ct=A.getClearAlpha(),ct<1&&A.setClearColor(16777215,.5),A.clear(),fe&&R.render(K);let Gt=A.toneMapping;A.toneMapping=li;let te=X.viewport;if(X.viewport!==void 0&&(X.viewport=void 0),S.setupLightsView(X),nt===!0&&J.setGlobalState(A.clippingPlanes,X),ao(C,K,X),Lt.updateMultisampleRenderTarget(xt),Lt.updateRenderTargetMipmap(xt),$t.has("WEBGL_multisampled_render_to_texture")===!1){let It=!1;for(let ee=0,Pe=F.length;ee<Pe;ee++){let Se=F[ee],{object:_e,geometry:Ze,material:Rt,group:hn}=Se;if(Rt.side===kn&&_e.layers.test(X.layers)){let le=Rt.side;Rt.side=je,Rt.needsUpdate=!0,uu(_e,K,X,Ze,Rt,hn),Rt.side=le,Rt.needsUpdate=!0,It=!0}}It===!0&&(Lt.updateMultisampleRenderTarget(xt),Lt.updateRenderTargetMipmap(xt))}A.setRenderTarget(bt,Mt,Nt),A.setClearColor(Y,ct),te!==void 0&&(X.viewport=te),A.toneMapping=Gt}function ao(C,F,K){let X=F.isScene===!0?F.overrideMaterial:null;for(let q=0,xt=C.length;q<xt;q++){let Et=C[q],{object:bt,geometry:Mt,group:Nt}=Et,Gt=Et.material;Gt.allowOverride===!0&&X!==null&&(Gt=X),bt.layers.test(K.layers)&&uu(bt,F,K,Mt,Gt,Nt)}}function uu(C,F,K,X,q,xt){N!==null&&q.isNodeMaterial&&N.setObject(C,q),C.onBeforeRender(A,F,K,X,q,xt),C.modelViewMatrix.multiplyMatrices(K.matrixWorldInverse,C.matrixWorld),C.normalMatrix.getNormalMatrix(C.modelViewMatrix),q.onBeforeRender(A,F,K,X,C,xt),q.transparent===!0&&q.side===kn&&q.forceSinglePass===!1?(q.side=je,q.needsUpdate=!0,A.renderBufferDirect(K,F,X,q,C,xt),q.side=ci,q.needsUpdate=!0,A.renderBufferDirect(K,F,X,q,C,xt),q.side=kn):A.renderBufferDirect(K,F,X,q,C,xt),C.onAfterRender(A,F,K,X,q,xt)}function fu(C){let F=0;for(let K of C)K.texture!==null&&F++;return F}function zs(C,F,K){F.isScene!==!0&&(F=be);let X=At.get(C),q=S.state.lights,xt=S.state.shadowsArray,Et=q.state.version,bt=tt.getParameters(C,q.state,xt,F,K,S.state.lightProbeGridArray),Mt=tt.getProgramCacheKey(bt),Nt=X.programs;X.environment=C.isMeshStandardMaterial||C.isMeshLambertMaterial||C.isMeshPhongMaterial?F.environment:null,X.fog=F.fog;let Gt=C.isMeshStandardMaterial||C.isMeshLambertMaterial&&!C.envMap||C.isMeshPhongMaterial&&!C.envMap;X.envMap=D.get(C.envMap||X.environment,Gt),X.envMapRotation=X.environment!==null&&C.envMap===null?F.environmentRotation:C.envMapRotation,Nt===void 0&&(C.addEventListener("dispose",re),Nt=new Map,X.programs=Nt,X.programVariants=new Map);let te=Nt.get(Mt);if(te!==void 0){if(X.currentProgram===te&&X.lightsStateVersion===Et)return mu(C,bt),te}else bt.uniforms=tt.getUniforms(C),N!==null&&C.isNodeMaterial&&N.build(C,K,bt),C.onBeforeCompile(bt,A),te=tt.acquireProgram(bt,Mt),Nt.set(Mt,te),X.uniforms=bt.uniforms;let It=X.uniforms;return(!C.isShaderMaterial&&!C.isRawShaderMaterial||C.clipping===!0)&&(It.clippingPlanes=J.uniform),mu(C,bt),X.needsLights=bg(C),X.lightsStateVersion=Et,X.needsLights&&(It.ambientLightColor.value=q.state.ambient,It.lightProbe.value=q.state.probe,It.sunLights.value=q.state.sun,It.sunLightShadows.value=q.state.sunShadow,It.directionalLights.value=q.state.directional,It.directionalLightShadows.value=q.state.directionalShadow,It.spotLights.value=q.state.spot,It.spotLightShadows.value=q.state.spotShadow,It.rectAreaLights.value=q.state.rectArea,It.ltc_1.value=q.state.rectAreaLTC1,It.ltc_2.value=q.state.rectAreaLTC2,It.pointLights.value=q.state.point,It.pointLightShadows.value=q.state.pointShadow,It.hemisphereLights.value=q.state.hemi,It.sunShadowMatrix.value=q.state.sunShadowMatrix,It.sunShadowCascade.value=q.state.sunShadowCascade,It.directionalShadowMatrix.value=q.state.directionalShadowMatrix,It.spotLightMatrix.value=q.state.spotLightMatrix,It.spotLightMap.value=q.state.spotLightMap,It.pointShadowMatrix.value=q.state.pointShadowMatrix),X.numLightProbeGrids=fu(S.state.lightProbeGridArray),X.currentProgram=te,X.uniformsList=null,te}function pg(C,F,K,X,q){let xt=At.get(C),Et=xt.currentProgram.id+","+X+","+q,bt=xt.programVariants.get(Et);return bt===void 0?(bt=zs(C,F,K),xt.programVariants.set(Et,bt)):(xt.currentProgram=bt,xt.uniformsList=null,xt.outputColorSpace=X,xt.toneMapping=q),bt}function pu(C){if(C.uniformsList===null){let F=C.currentProgram.getUniforms();C.uniformsList=ps.seqWithValue(F.seq,C.uniforms)}return C.uniformsList}function mu(C,F){let K=At.get(C);K.outputColorSpace=F.outputColorSpace,K.batching=F.batching,K.batchingColor=F.batchingColor,K.instancing=F.instancing,K.instancingColor=F.instancingColor,K.instancingMorph=F.instancingMorph,K.skinning=F.skinning,K.morphTargets=F.morphTargets,K.morphNormals=F.morphNormals,K.morphColors=F.morphColors,K.morphTargetsCount=F.morphTargetsCount,K.numClippingPlanes=F.numClippingPlanes,K.numIntersection=F.numClipIntersection,K.vertexAlphas=F.vertexAlphas,K.vertexTangents=F.vertexTangents,K.toneMapping=F.toneMapping}function mg(C,F,K,X,q){F.isScene!==!0&&(F=be),Lt.resetTextureUnits();let xt=F.fog,Et=X.isMeshStandardMaterial||X.isMeshLambertMaterial||X.isMeshPhongMaterial?F.environment:null,bt=Q===null?A.outputColorSpace:Q.isXRRenderTarget===!0?Q.texture.colorSpace:Kt.workingColorSpace,Mt=X.isMeshStandardMaterial||X.isMeshLambertMaterial&&!X.envMap||X.isMeshPhongMaterial&&!X.envMap,Nt=D.get(X.envMap||Et,Mt),Gt=X.vertexColors===!0&&!!K.attributes.color&&K.attributes.color.itemSize===4,te=!!K.attributes.tangent&&(!!X.normalMap||X.anisotropy>0),It=!!K.morphAttributes.position,ee=!!K.morphAttributes.normal,Pe=!!K.morphAttributes.color,Se=li;X.toneMapped&&(Q===null||Q.isXRRenderTarget===!0)&&(Se=A.toneMapping);let _e=K.morphAttributes.position||K.morphAttributes.normal||K.morphAttributes.color,Ze=_e!==void 0?_e.length:0,Rt=At.get(X),hn=S.state.lights;if(nt===!0&&(St===!0||C!==Z)){let Ie=C===Z&&X.id===G;J.setState(X,C,Ie)}let le=!1,ca=!1;X.version===Rt.__version?Rt.needsLights&&Rt.lightsStateVersion!==hn.state.version||q.isBatchedMesh&&Rt.batching===!1||!q.isBatchedMesh&&Rt.batching===!0||q.isBatchedMesh&&Rt.batchingColor===!0&&q._colorsTexture===null||q.isBatchedMesh&&Rt.batchingColor===!1&&q._colorsTexture!==null||q.isInstancedMesh&&Rt.instancing===!1||!q.isInstancedMesh&&Rt.instancing===!0||q.isSkinnedMesh&&Rt.skinning===!1||!q.isSkinnedMesh&&Rt.skinning===!0||q.isInstancedMesh&&Rt.instancingColor===!0&&q.instanceColor===null||q.isInstancedMesh&&Rt.instancingColor===!1&&q.instanceColor!==null||q.isInstancedMesh&&Rt.instancingMorph===!0&&q.morphTexture===null||q.isInstancedMesh&&Rt.instancingMorph===!1&&q.morphTexture!==null||Rt.envMap!==Nt||X.fog===!0&&Rt.fog!==xt||Rt.numClippingPlanes!==void 0&&(Rt.numClippingPlanes!==J.numPlanes||Rt.numIntersection!==J.numIntersection)||Rt.vertexAlphas!==Gt||Rt.vertexTangents!==te||Rt.morphTargets!==It||Rt.morphNormals!==ee||Rt.morphColors!==Pe||Rt.morphTargetsCount!==Ze||Rt.numLightProbeGrids!==fu(S.state.lightProbeGridArray)?le=!0:(Rt.outputColorSpace!==bt||Rt.toneMapping!==Se)&&(ca=!0):(le=!0,Rt.__version=X.version);let Qe=Rt.currentProgram;(le===!0||ca===!0)&&(Qe=ca===!0?pg(X,F,q,bt,Se):zs(X,F,q),N&&X.isNodeMaterial&&N.onUpdateProgram(X,Qe,Rt));let so=!1,Fi=!1,la=!1,ae=Qe.getUniforms(),We=Rt.uniforms;if(dt.useProgram(Qe.program)&&(so=!0,Fi=!0,la=!0),X.id!==G&&(G=X.id,Fi=!0),so||Z!==C){dt.buffers.depth.getReversed()&&C.reversedDepth!==!0&&(C._reversedDepth=!0,C.updateProjectionMatrix()),ae.setValue(B,"projectionMatrix",C.projectionMatrix),ae.setValue(B,"viewMatrix",C.matrixWorldInverse);let Ve=ae.map.cameraPosition;Ve!==void 0&&Ve.setValue(B,Qt.setFromMatrixPosition(C.matrixWorld)),Jt.logarithmicDepthBuffer&&ae.setValue(B,"logDepthBufFC",2/(Math.log(C.far+1)/Math.LN2)),(X.isMeshPhongMaterial||X.isMeshToonMaterial||X.isMeshLambertMaterial||X.isMeshBasicMaterial||X.isMeshStandardMaterial||X.isShaderMaterial)&&ae.setValue(B,"isOrthographic",C.isOrthographicCamera===!0),Z!==C&&(Z=C,Fi=!0,la=!0)}if(Rt.needsLights&&(hn.state.sunShadowMap.length>0&&ae.setValue(B,"sunShadowMap",hn.state.sunShadowMap,Lt),hn.state.directionalShadowMap.length>0&&ae.setValue(B,"directionalShadowMap",hn.state.directionalShadowMap,Lt),hn.state.spotShadowMap.length>0&&ae.setValue(B,"spotShadowMap",hn.state.spotShadowMap,Lt),hn.state.pointShadowMap.length>0&&ae.setValue(B,"pointShadowMap",hn.state.pointShadowMap,Lt)),q.isSkinnedMesh){ae.setOptional(B,q,"bindMatrix"),ae.setOptional(B,q,"bindMatrixInverse");let Ie=q.skeleton;Ie&&(Ie.boneTexture===null&&Ie.computeBoneTexture(),ae.setValue(B,"boneTexture",Ie.boneTexture,Lt))}q.isBatchedMesh&&(ae.setOptional(B,q,"batchingTexture"),ae.setValue(B,"batchingTexture",q._matricesTexture,Lt),ae.setOptional(B,q,"batchingIdTexture"),ae.setValue(B,"batchingIdTexture",q._indirectTexture,Lt),ae.setOptional(B,q,"batchingColorTexture"),q._colorsTexture!==null&&ae.setValue(B,"batchingColorTexture",q._colorsTexture,Lt));let Wn=K.morphAttributes;if((Wn.position!==void 0||Wn.normal!==void 0||Wn.color!==void 0)&&k.update(q,K,Qe),(Fi||Rt.receiveShadow!==q.receiveShadow)&&(Rt.receiveShadow=q.receiveShadow,ae.setValue(B,"receiveShadow",q.receiveShadow)),(X.isMeshStandardMaterial||X.isMeshLambertMaterial||X.isMeshPhongMaterial)&&X.envMap===null&&F.environment!==null&&(We.envMapIntensity.value=F.environmentIntensity),We.dfgLUT!==void 0&&(We.dfgLUT.value=hv()),Fi){if(ae.setValue(B,"toneMappingExposure",A.toneMappingExposure),Rt.needsLights&&gg(We,la),xt&&X.fog===!0&&lt.refreshFogUniforms(We,xt),lt.refreshMaterialUniforms(We,X,gt,Tt,S.state.transmissionRenderTarget[C.id]),Rt.needsLights&&Rt.numLightProbeGrids>0){let Ie=p,Ve=0;for(let xi of S.state.lightProbeGridArray)xi.texture!==null&&(Ie.textures[Ve]=xi.texture,Ie.min[Ve]=xi.boundingBox.min,Ie.max[Ve]=xi.boundingBox.max,Ie.resolution[Ve]=xi.resolution,Ve++);for(let xi in Ie)Ie[xi].length=Ve;We.probesSH.value=Ie.textures,We.probesMin.value=Ie.min,We.probesMax.value=Ie.max,We.probesResolution.value=Ie.resolution}ps.upload(B,pu(Rt),We,Lt)}if(X.isShaderMaterial&&X.uniformsNeedUpdate===!0&&(ps.upload(B,pu(Rt),We,Lt),X.uniformsNeedUpdate=!1),X.isSpriteMaterial&&ae.setValue(B,"center",q.center),ae.setValue(B,"modelViewMatrix",q.modelViewMatrix),ae.setValue(B,"normalMatrix",q.normalMatrix),ae.setValue(B,"modelMatrix",q.matrixWorld),X.uniformsGroups!==void 0){let Ie=X.uniformsGroups;for(let Ve=0,xi=Ie.length;Ve<xi;Ve++){let bu=Ie[Ve];_t.update(bu,Qe),_t.bind(bu,Qe)}}return Qe}function gg(C,F){C.ambientLightColor.needsUpdate=F,C.lightProbe.needsUpdate=F,C.sunLights.needsUpdate=F,C.sunLightShadows.needsUpdate=F,C.directionalLights.needsUpdate=F,C.directionalLightShadows.needsUpdate=F,C.pointLights.needsUpdate=F,C.pointLightShadows.needsUpdate=F,C.spotLights.needsUpdate=F,C.spotLightShadows.needsUpdate=F,C.rectAreaLights.needsUpdate=F,C.hemisphereLights.needsUpdate=F}function bg(C){return C.isMeshLambertMaterial||C.isMeshToonMaterial||C.isMeshPhongMaterial||C.isMeshStandardMaterial||C.isShadowMaterial||C.isShaderMaterial&&C.lights===!0}this.getActiveCubeFace=function(){return V},this.getActiveMipmapLevel=function(){return O},this.getRenderTarget=function(){return Q},this.setRenderTargetTextures=function(C,F,K){let X=At.get(C);X.__autoAllocateDepthBuffer=C.resolveDepthBuffer===!1,X.__autoAllocateDepthBuffer===!1&&(X.__useRenderToTexture=!1),At.get(C.texture).__webglTexture=F,At.get(C.depthTexture).__webglTexture=X.__autoAllocateDepthBuffer?void 0:K,X.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(C,F){let K=At.get(C);K.__webglFramebuffer=F,K.__useDefaultFramebuffer=F===void 0},this.setRenderTarget=function(C,F=0,K=0){Q=C,V=F,O=K;let X=null,q=!1,xt=!1;if(C){let bt=At.get(C);if(bt.__useDefaultFramebuffer!==void 0){dt.bindFramebuffer(B.FRAMEBUFFER,bt.__webglFramebuffer),et.copy(C.viewport),ht.copy(C.scissor),Pt=C.scissorTest,dt.viewport(et),dt.scissor(ht),dt.setScissorTest(Pt),G=-1;return}else if(bt.__webglFramebuffer===void 0)Lt.setupRenderTarget(C);else if(bt.__hasExternalTextures)Lt.rebindTextures(C,At.get(C.texture).__webglTexture,At.get(C.depthTexture).__webglTexture);else if(C.depthBuffer){let Gt=C.depthTexture;if(bt.__boundDepthTexture!==Gt){if(Gt!==null&&At.has(Gt)&&(C.width!==Gt.image.width||C.height!==Gt.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");Lt.setupDepthRenderbuffer(C)}}let Mt=C.texture;(Mt.isData3DTexture||Mt.isDataArrayTexture||Mt.isCompressedArrayTexture)&&(xt=!0);let Nt=At.get(C).__webglFramebuffer;C.isWebGLCubeRenderTarget?(Array.isArray(Nt[F])?X=Nt[F][K]:X=Nt[F],q=!0):C.samples>0&&Lt.useMultisampledRTT(C)===!1?X=At.get(C).__webglMultisampledFramebuffer:Array.isArray(Nt)?X=Nt[K]:X=Nt,et.copy(C.viewport),ht.copy(C.scissor),Pt=C.scissorTest}else et.copy(Dt).multiplyScalar(gt).floor(),ht.copy(kt).multiplyScalar(gt).floor(),Pt=Yt;if(K!==0&&(X=L),dt.bindFramebuffer(B.FRAMEBUFFER,X)&&dt.drawBuffers(C,X),dt.viewport(et),dt.scissor(ht),dt.setScissorTest(Pt),q){let bt=At.get(C.texture);B.framebufferTexture2D(B.FRAMEBUFFER,B.COLOR_ATTACHMENT0,B.TEXTURE_CUBE_MAP_POSITIVE_X+F,bt.__webglTexture,K)}else if(xt){let bt=F;for(let Mt=0;Mt<C.textures.length;Mt++){let Nt=At.get(C.textures[Mt]);B.framebufferTextureLayer(B.FRAMEBUFFER,B.COLOR_ATTACHMENT0+Mt,Nt.__webglTexture,K,bt)}}else if(C!==null&&K!==0){let bt=At.get(C.texture);B.framebufferTexture2D(B.FRAMEBUFFER,B.COLOR_ATTACHMENT0,B.TEXTURE_2D,bt.__webglTexture,K)}G=-1};function gu(C){let F=At.get(C);return(F.__readFormat!==C.format||F.__readType!==C.type)&&(F.__readFormat=C.format,F.__readType=C.type,F.__formatReadable=Jt.textureFormatReadable(C.format),F.__typeReadable=Jt.textureTypeReadable(C.type)),F}this.readRenderTargetPixels=function(C,F,K,X,q,xt,Et,bt=0){if(!(C&&C.isWebGLRenderTarget)){zt("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let Mt=At.get(C).__webglFramebuffer;if(C.isWebGLCubeRenderTarget&&Et!==void 0&&(Mt=Mt[Et],Array.isArray(Mt)&&(Mt=Mt[0])),Mt){dt.bindFramebuffer(B.FRAMEBUFFER,Mt);try{let Nt=C.textures[bt],Gt=Nt.format,te=Nt.type;C.textures.length>1&&B.readBuffer(B.COLOR_ATTACHMENT0+bt);let It=gu(Nt);if(It.__formatReadable===!1){zt("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(It.__typeReadable===!1){zt("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}F>=0&&F<=C.width-X&&K>=0&&K<=C.height-q&&B.readPixels(F,K,X,q,it.convert(Gt),it.convert(te),xt)}finally{let Nt=Q!==null?At.get(Q).__webglFramebuffer:null;dt.bindFramebuffer(B.FRAMEBUFFER,Nt)}}},this.readRenderTargetPixelsAsync=async function(C,F,K,X,q,xt,Et,bt=0){if(!(C&&C.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let Mt=At.get(C).__webglFramebuffer;if(C.isWebGLCubeRenderTarget&&Et!==void 0&&(Mt=Mt[Et],Array.isArray(Mt)&&(Mt=Mt[0])),Mt)if(F>=0&&F<=C.width-X&&K>=0&&K<=C.height-q){dt.bindFramebuffer(B.FRAMEBUFFER,Mt);let Nt=C.textures[bt],Gt=Nt.format,te=Nt.type;C.textures.length>1&&B.readBuffer(B.COLOR_ATTACHMENT0+bt);let It=gu(Nt);if(It.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(It.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");let ee=B.createBuffer();B.bindBuffer(B.PIXEL_PACK_BUFFER,ee),B.bufferData(B.PIXEL_PACK_BUFFER,xt.byteLength,B.STREAM_READ),B.readPixels(F,K,X,q,it.convert(Gt),it.convert(te),0),B.bindBuffer(B.PIXEL_PACK_BUFFER,null);let Pe=Q!==null?At.get(Q).__webglFramebuffer:null;dt.bindFramebuffer(B.FRAMEBUFFER,Pe);let Se=B.fenceSync(B.SYNC_GPU_COMMANDS_COMPLETE,0);return B.flush(),await Ff(B,Se,4),B.bindBuffer(B.PIXEL_PACK_BUFFER,ee),B.getBufferSubData(B.PIXEL_PACK_BUFFER,0,xt),B.bindBuffer(B.PIXEL_PACK_BUFFER,null),B.deleteBuffer(ee),B.deleteSync(Se),xt}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(C,F=null,K=0){let X=Math.pow(2,-K),q=Math.floor(C.image.width*X),xt=Math.floor(C.image.height*X),Et=F!==null?F.x:0,bt=F!==null?F.y:0;Lt.setTexture2D(C,0),B.copyTexSubImage2D(B.TEXTURE_2D,K,0,0,Et,bt,q,xt),dt.unbindTexture()},this.copyTextureToTexture=function(C,F,K=null,X=null,q=0,xt=0){let Et,bt,Mt,Nt,Gt,te,It,ee,Pe,Se=C.isCompressedTexture?C.mipmaps[xt]:C.image;if(K!==null)Et=K.max.x-K.min.x,bt=K.max.y-K.min.y,Mt=K.isBox3?K.max.z-K.min.z:1,Nt=K.min.x,Gt=K.min.y,te=K.isBox3?K.min.z:0;else{let ae=Math.pow(2,-q);Et=Math.floor(Se.width*ae),bt=Math.floor(Se.height*ae),C.isDataArrayTexture?Mt=Se.depth:C.isData3DTexture?Mt=Math.floor(Se.depth*ae):Mt=1,Nt=0,Gt=0,te=0}X!==null?(It=X.x,ee=X.y,Pe=X.z):(It=0,ee=0,Pe=0);let _e=it.convert(F.format),Ze=it.convert(F.type),Rt;F.isData3DTexture?(Lt.setTexture3D(F,0),Rt=B.TEXTURE_3D):F.isDataArrayTexture||F.isCompressedArrayTexture?(Lt.setTexture2DArray(F,0),Rt=B.TEXTURE_2D_ARRAY):(Lt.setTexture2D(F,0),Rt=B.TEXTURE_2D),dt.activeTexture(B.TEXTURE0),dt.pixelStorei(B.UNPACK_FLIP_Y_WEBGL,F.flipY),dt.pixelStorei(B.UNPACK_PREMULTIPLY_ALPHA_WEBGL,F.premultiplyAlpha),dt.pixelStorei(B.UNPACK_ALIGNMENT,F.unpackAlignment);let hn=dt.getParameter(B.UNPACK_ROW_LENGTH),le=dt.getParameter(B.UNPACK_IMAGE_HEIGHT),ca=dt.getParameter(B.UNPACK_SKIP_PIXELS),Qe=dt.getParameter(B.UNPACK_SKIP_ROWS),so=dt.getParameter(B.UNPACK_SKIP_IMAGES);dt.pixelStorei(B.UNPACK_ROW_LENGTH,Se.width),dt.pixelStorei(B.UNPACK_IMAGE_HEIGHT,Se.height),dt.pixelStorei(B.UNPACK_SKIP_PIXELS,Nt),dt.pixelStorei(B.UNPACK_SKIP_ROWS,Gt),dt.pixelStorei(B.UNPACK_SKIP_IMAGES,te);let Fi=C.isDataArrayTexture||C.isData3DTexture,la=F.isDataArrayTexture||F.isData3DTexture;if(C.isDepthTexture){let ae=At.get(C),We=At.get(F),Wn=At.get(ae.__renderTarget),Ie=At.get(We.__renderTarget);dt.bindFramebuffer(B.READ_FRAMEBUFFER,Wn.__webglFramebuffer),dt.bindFramebuffer(B.DRAW_FRAMEBUFFER,Ie.__webglFramebuffer);for(let Ve=0;Ve<Mt;Ve++)Fi&&(B.framebufferTextureLayer(B.READ_FRAMEBUFFER,B.COLOR_ATTACHMENT0,At.get(C).__webglTexture,q,te+Ve),B.framebufferTextureLayer(B.DRAW_FRAMEBUFFER,B.COLOR_ATTACHMENT0,At.get(F).__webglTexture,xt,Pe+Ve)),B.blitFramebuffer(Nt,Gt,Nt+Et,Gt+bt,It,ee,It+Et,ee+bt,B.DEPTH_BUFFER_BIT,B.NEAREST);dt.bindFramebuffer(B.READ_FRAMEBUFFER,null),dt.bindFramebuffer(B.DRAW_FRAMEBUFFER,null)}else if(q!==0||C.isRenderTargetTexture||At.has(C)){let ae=At.get(C),We=At.get(F);dt.bindFramebuffer(B.READ_FRAMEBUFFER,P),dt.bindFramebuffer(B.DRAW_FRAMEBUFFER,U);for(let Wn=0;Wn<Mt;Wn++)Fi?B.framebufferTextureLayer(B.READ_FRAMEBUFFER,B.COLOR_ATTACHMENT0,ae.__webglTexture,q,te+Wn):B.framebufferTexture2D(B.READ_FRAMEBUFFER,B.COLOR_ATTACHMENT0,B.TEXTURE_2D,ae.__webglTexture,q),la?B.framebufferTextureLayer(B.DRAW_FRAMEBUFFER,B.COLOR_ATTACHMENT0,We.__webglTexture,xt,Pe+Wn):B.framebufferTexture2D(B.DRAW_FRAMEBUFFER,B.COLOR_ATTACHMENT0,B.TEXTURE_2D,We.__webglTexture,xt),q!==0?B.blitFramebuffer(Nt,Gt,Nt+Et,Gt+bt,It,ee,It+Et,ee+bt,B.COLOR_BUFFER_BIT,B.NEAREST):la?B.copyTexSubImage3D(Rt,xt,It,ee,Pe+Wn,Nt,Gt,Et,bt):B.copyTexSubImage2D(Rt,xt,It,ee,Nt,Gt,Et,bt);dt.bindFramebuffer(B.READ_FRAMEBUFFER,null),dt.bindFramebuffer(B.DRAW_FRAMEBUFFER,null)}else la?C.isDataTexture||C.isData3DTexture?B.texSubImage3D(Rt,xt,It,ee,Pe,Et,bt,Mt,_e,Ze,Se.data):F.isCompressedArrayTexture?B.compressedTexSubImage3D(Rt,xt,It,ee,Pe,Et,bt,Mt,_e,Se.data):B.texSubImage3D(Rt,xt,It,ee,Pe,Et,bt,Mt,_e,Ze,Se):C.isDataTexture?B.texSubImage2D(B.TEXTURE_2D,xt,It,ee,Et,bt,_e,Ze,Se.data):C.isCompressedTexture?B.compressedTexSubImage2D(B.TEXTURE_2D,xt,It,ee,Se.width,Se.height,_e,Se.data):B.texSubImage2D(B.TEXTURE_2D,xt,It,ee,Et,bt,_e,Ze,Se);dt.pixelStorei(B.UNPACK_ROW_LENGTH,hn),dt.pixelStorei(B.UNPACK_IMAGE_HEIGHT,le),dt.pixelStorei(B.UNPACK_SKIP_PIXELS,ca),dt.pixelStorei(B.UNPACK_SKIP_ROWS,Qe),dt.pixelStorei(B.UNPACK_SKIP_IMAGES,so),xt===0&&F.generateMipmaps===!0&&F.mipmapsAutoUpdate===!0&&B.generateMipmap(Rt),dt.unbindTexture()},this.initRenderTarget=function(C){At.get(C).__webglFramebuffer===void 0&&Lt.setupRenderTarget(C)},this.initTexture=function(C){C.isCubeTexture?Lt.setTextureCube(C,0):C.isData3DTexture?Lt.setTexture3D(C,0):C.isDataArrayTexture||C.isCompressedArrayTexture?Lt.setTexture2DArray(C,0):Lt.setTexture2D(C,0),dt.unbindTexture()},this.resetState=function(){V=0,O=0,Q=null,dt.reset(),st.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return Fn}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(t){this._outputColorSpace=t;let e=this.getContext();e.drawingBufferColorSpace=Kt._getDrawingBufferColorSpace(t),e.unpackColorSpace=Kt._getUnpackColorSpace()}}});function uv(i){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(i.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(i)&&(this._addPointer(i),i.pointerType==="touch"?this._onTouchStart(i):this._onMouseDown(i),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function fv(i){this.enabled!==!1&&(i.pointerType==="touch"?this._onTouchMove(i):this._onMouseMove(i))}function pv(i){switch(this._removePointer(i),this._pointers.length){case 0:this.domElement.releasePointerCapture(i.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(Mp),this.state=he.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:let t=this._pointers[0],e=this._pointerPositions[t];this._onTouchStart({pointerId:t,pageX:e.x,pageY:e.y});break}}function mv(i){let t;switch(i.button){case 0:t=this.mouseButtons.LEFT;break;case 1:t=this.mouseButtons.MIDDLE;break;case 2:t=this.mouseButtons.RIGHT;break;default:t=-1}switch(t){case qi.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(i),this.state=he.DOLLY;break;case qi.ROTATE:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=he.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=he.ROTATE}break;case qi.PAN:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=he.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=he.PAN}break;default:this.state=he.NONE}this.state!==he.NONE&&this.dispatchEvent(Sd)}function gv(i){switch(this.state){case he.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(i);break;case he.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(i);break;case he.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(i);break}}function bv(i){this.enabled===!1||this.enableZoom===!1||this.state!==he.NONE||(i.preventDefault(),this.dispatchEvent(Sd),this._handleMouseWheel(this._customWheelEvent(i)),this.dispatchEvent(Mp))}function xv(i){this.enabled!==!1&&this._handleKeyDown(i)}function yv(i){switch(this._trackPointer(i),this._pointers.length){case 1:switch(this.touches.ONE){case oi.ROTATE:if(this.enableRotate===!1){this.state=he.NONE;break}this._handleTouchStartRotate(i),this.state=he.TOUCH_ROTATE;break;case oi.PAN:if(this.enablePan===!1){this.state=he.NONE;break}this._handleTouchStartPan(i),this.state=he.TOUCH_PAN;break;default:this.state=he.NONE}break;case 2:switch(this.touches.TWO){case oi.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(i),this.state=he.TOUCH_DOLLY_PAN;break;case oi.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(i),this.state=he.TOUCH_DOLLY_ROTATE;break;default:this.state=he.NONE}break;default:this.state=he.NONE}this.state!==he.NONE&&this.dispatchEvent(Sd)}function _v(i){switch(this._trackPointer(i),this.state){case he.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(i),this.update();break;case he.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(i),this.update();break;case he.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(i),this.update();break;case he.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(i),this.update();break;default:this.state=he.NONE}}function vv(i){this.enabled!==!1&&i.preventDefault()}function Mv(i){i.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function Sv(i){i.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}var _p,Sd,Mp,rl,vp,dv,ze,En,he,Md,ol,Sp=ha(()=>{gs();_p={type:"change"},Sd={type:"start"},Mp={type:"end"},rl=new Kn,vp=new un,dv=Math.cos(70*wa.DEG2RAD),ze=new z,En=2*Math.PI,he={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},Md=1e-6,ol=class extends Er{constructor(t,e=null){super(t,e),this.state=he.NONE,this.target=new z,this.cursor=new z,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:qi.ROTATE,MIDDLE:qi.DOLLY,RIGHT:qi.PAN},this.touches={ONE:oi.ROTATE,TWO:oi.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new z,this._lastQuaternion=new Cn,this._lastTargetPosition=new z,this._quat=new Cn().setFromUnitVectors(t.up,new z(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new os,this._sphericalDelta=new os,this._scale=1,this._panOffset=new z,this._rotateStart=new Bt,this._rotateEnd=new Bt,this._rotateDelta=new Bt,this._panStart=new Bt,this._panEnd=new Bt,this._panDelta=new Bt,this._dollyStart=new Bt,this._dollyEnd=new Bt,this._dollyDelta=new Bt,this._dollyDirection=new z,this._mouse=new Bt,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=fv.bind(this),this._onPointerDown=uv.bind(this),this._onPointerUp=pv.bind(this),this._onContextMenu=vv.bind(this),this._onMouseWheel=bv.bind(this),this._onKeyDown=xv.bind(this),this._onTouchStart=yv.bind(this),this._onTouchMove=_v.bind(this),this._onMouseDown=mv.bind(this),this._onMouseMove=gv.bind(this),this._interceptControlDown=Mv.bind(this),this._interceptControlUp=Sv.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(t){this._cursorStyle=t,t==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(t){super.connect(t),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=he.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(t){t.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=t}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(_p),this.update(),this.state=he.NONE}pan(t,e){this._pan(t,e),this.update()}dollyIn(t){this._dollyIn(t),this.update()}dollyOut(t){this._dollyOut(t),this.update()}rotateLeft(t){this._rotateLeft(t),this.update()}rotateUp(t){this._rotateUp(t),this.update()}update(t=null){let e=this.object.position;ze.copy(e).sub(this.target),ze.applyQuaternion(this._quat),this._spherical.setFromVector3(ze),this.autoRotate&&this.state===he.NONE&&this._rotateLeft(this._getAutoRotationAngle(t)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let n=this.minAzimuthAngle,a=this.maxAzimuthAngle;isFinite(n)&&isFinite(a)&&(n<-Math.PI?n+=En:n>Math.PI&&(n-=En),a<-Math.PI?a+=En:a>Math.PI&&(a-=En),n<=a?this._spherical.theta=Math.max(n,Math.min(a,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(n+a)/2?Math.max(n,this._spherical.theta):Math.min(a,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let s=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{let r=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),s=r!=this._spherical.radius}if(ze.setFromSpherical(this._spherical),ze.applyQuaternion(this._quatInverse),e.copy(this.target).add(ze),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let r=null;if(this.object.isPerspectiveCamera){let o=ze.length();r=this._clampDistance(o*this._scale);let c=o-r;this.object.position.addScaledVector(this._dollyDirection,c),this.object.updateMatrixWorld(),s=!!c}else if(this.object.isOrthographicCamera){let o=new z(this._mouse.x,this._mouse.y,0);o.unproject(this.object);let c=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),s=c!==this.object.zoom;let l=new z(this._mouse.x,this._mouse.y,0);l.unproject(this.object),this.object.position.sub(l).add(o),this.object.updateMatrixWorld(),r=ze.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;r!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(r).add(this.object.position):(rl.origin.copy(this.object.position),rl.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(rl.direction))<dv?this.object.lookAt(this.target):(vp.setFromNormalAndCoplanarPoint(this.object.up,this.target),rl.intersectPlane(vp,this.target))))}else if(this.object.isOrthographicCamera){let r=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),r!==this.object.zoom&&(this.object.updateProjectionMatrix(),s=!0)}return this._scale=1,this._performCursorZoom=!1,s||this._lastPosition.distanceToSquared(this.object.position)>Md||8*(1-this._lastQuaternion.dot(this.object.quaternion))>Md||this._lastTargetPosition.distanceToSquared(this.target)>Md?(this.dispatchEvent(_p),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(t){return t!==null?En/60*this.autoRotateSpeed*t:En/60/60*this.autoRotateSpeed}_getZoomScale(t){let e=Math.abs(t*.01);return Math.pow(.95,this.zoomSpeed*e)}_rotateLeft(t){this._sphericalDelta.theta-=t}_rotateUp(t){this._sphericalDelta.phi-=t}_panLeft(t,e){ze.setFromMatrixColumn(e,0),ze.multiplyScalar(-t),this._panOffset.add(ze)}_panUp(t,e){this.screenSpacePanning===!0?ze.setFromMatrixColumn(e,1):(ze.setFromMatrixColumn(e,0),ze.crossVectors(this.object.up,ze)),ze.multiplyScalar(t),this._panOffset.add(ze)}_pan(t,e){let n=this.domElement;if(this.object.isPerspectiveCamera){let a=this.object.position;ze.copy(a).sub(this.target);let s=ze.length();s*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*t*s/n.clientHeight,this.object.matrix),this._panUp(2*e*s/n.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(t*(this.object.right-this.object.left)/this.object.zoom/n.clientWidth,this.object.matrix),this._panUp(e*(this.object.top-this.object.bottom)/this.object.zoom/n.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(t){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=t:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(t){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=t:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(t,e){if(!this.zoomToCursor)return;this._performCursorZoom=!0;let n=this.domElement.getBoundingClientRect(),a=t-n.left,s=e-n.top,r=n.width,o=n.height;this._mouse.x=a/r*2-1,this._mouse.y=-(s/o)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(t){return Math.max(this.minDistance,Math.min(this.maxDistance,t))}_handleMouseDownRotate(t){this._rotateStart.set(t.clientX,t.clientY)}_handleMouseDownDolly(t){this._updateZoomParameters(t.clientX,t.clientY),this._dollyStart.set(t.clientX,t.clientY)}_handleMouseDownPan(t){this._panStart.set(t.clientX,t.clientY)}_handleMouseMoveRotate(t){this._rotateEnd.set(t.clientX,t.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let e=this.domElement;this._rotateLeft(En*this._rotateDelta.x/e.clientHeight),this._rotateUp(En*this._rotateDelta.y/e.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(t){this._dollyEnd.set(t.clientX,t.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(t){this._panEnd.set(t.clientX,t.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(t){this._updateZoomParameters(t.clientX,t.clientY),t.deltaY<0?this._dollyIn(this._getZoomScale(t.deltaY)):t.deltaY>0&&this._dollyOut(this._getZoomScale(t.deltaY)),this.update()}_handleKeyDown(t){let e=!1;switch(t.code){case this.keys.UP:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateUp(En*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),e=!0;break;case this.keys.BOTTOM:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateUp(-En*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),e=!0;break;case this.keys.LEFT:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateLeft(En*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),e=!0;break;case this.keys.RIGHT:t.ctrlKey||t.metaKey||t.shiftKey?this.enableRotate&&this._rotateLeft(-En*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),e=!0;break}e&&(t.preventDefault(),this.update())}_handleTouchStartRotate(t){if(this._pointers.length===1)this._rotateStart.set(t.pageX,t.pageY);else{let e=this._getSecondPointerPosition(t),n=.5*(t.pageX+e.x),a=.5*(t.pageY+e.y);this._rotateStart.set(n,a)}}_handleTouchStartPan(t){if(this._pointers.length===1)this._panStart.set(t.pageX,t.pageY);else{let e=this._getSecondPointerPosition(t),n=.5*(t.pageX+e.x),a=.5*(t.pageY+e.y);this._panStart.set(n,a)}}_handleTouchStartDolly(t){let e=this._getSecondPointerPosition(t),n=t.pageX-e.x,a=t.pageY-e.y,s=Math.sqrt(n*n+a*a);this._dollyStart.set(0,s)}_handleTouchStartDollyPan(t){this.enableZoom&&this._handleTouchStartDolly(t),this.enablePan&&this._handleTouchStartPan(t)}_handleTouchStartDollyRotate(t){this.enableZoom&&this._handleTouchStartDolly(t),this.enableRotate&&this._handleTouchStartRotate(t)}_handleTouchMoveRotate(t){if(this._pointers.length==1)this._rotateEnd.set(t.pageX,t.pageY);else{let n=this._getSecondPointerPosition(t),a=.5*(t.pageX+n.x),s=.5*(t.pageY+n.y);this._rotateEnd.set(a,s)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let e=this.domElement;this._rotateLeft(En*this._rotateDelta.x/e.clientHeight),this._rotateUp(En*this._rotateDelta.y/e.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(t){if(this._pointers.length===1)this._panEnd.set(t.pageX,t.pageY);else{let e=this._getSecondPointerPosition(t),n=.5*(t.pageX+e.x),a=.5*(t.pageY+e.y);this._panEnd.set(n,a)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(t){let e=this._getSecondPointerPosition(t),n=t.pageX-e.x,a=t.pageY-e.y,s=Math.sqrt(n*n+a*a);this._dollyEnd.set(0,s),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);let r=(t.pageX+e.x)*.5,o=(t.pageY+e.y)*.5;this._updateZoomParameters(r,o)}_handleTouchMoveDollyPan(t){this.enableZoom&&this._handleTouchMoveDolly(t),this.enablePan&&this._handleTouchMovePan(t)}_handleTouchMoveDollyRotate(t){this.enableZoom&&this._handleTouchMoveDolly(t),this.enableRotate&&this._handleTouchMoveRotate(t)}_addPointer(t){this._pointers.push(t.pointerId)}_removePointer(t){delete this._pointerPositions[t.pointerId];for(let e=0;e<this._pointers.length;e++)if(this._pointers[e]==t.pointerId){this._pointers.splice(e,1);return}}_isTrackingPointer(t){for(let e=0;e<this._pointers.length;e++)if(this._pointers[e]==t.pointerId)return!0;return!1}_trackPointer(t){let e=this._pointerPositions[t.pointerId];e===void 0&&(e=new Bt,this._pointerPositions[t.pointerId]=e),e.set(t.pageX,t.pageY)}_getSecondPointerPosition(t){let e=t.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[e]}_customWheelEvent(t){let e=t.deltaMode,n={clientX:t.clientX,clientY:t.clientY,deltaY:t.deltaY};switch(e){case 1:n.deltaY*=16;break;case 2:n.deltaY*=100;break}return t.ctrlKey&&!this._controlActive&&(n.deltaY*=10),n}}});var bs,wd=ha(()=>{gs();yt.line={worldUnits:{value:1},linewidth:{value:1},resolution:{value:new Bt},dashOffset:{value:0},dashScale:{value:1},dashSize:{value:1},gapSize:{value:1}};xn.line={uniforms:Br.merge([yt.common,yt.fog,yt.line]),vertexShader:`
		#include <common>
		#include <color_pars_vertex>
		#include <fog_pars_vertex>
		#include <logdepthbuf_pars_vertex>
		#include <clipping_planes_pars_vertex>

		uniform float linewidth;
		uniform vec2 resolution;

		attribute vec3 instanceStart;
		attribute vec3 instanceEnd;

		attribute vec3 instanceColorStart;
		attribute vec3 instanceColorEnd;

		#ifdef WORLD_UNITS

			varying vec4 worldPos;
			varying vec3 worldStart;
			varying vec3 worldEnd;

			#ifdef USE_DASH

				varying vec2 vUv;

			#endif

		#else

			varying vec2 vUv;

		#endif

		#ifdef USE_DASH

			uniform float dashScale;
			attribute float instanceDistanceStart;
			attribute float instanceDistanceEnd;
			varying float vLineDistance;

		#endif

		float trimSegmentAlpha( const in vec4 start, const in vec4 end ) {

			// compute the interpolation factor needed to trim the segment so it terminates
			// between the camera plane and the near plane

			// conservative estimate of the near plane
			float a = projectionMatrix[ 2 ][ 2 ]; // 3nd entry in 3th column
			float b = projectionMatrix[ 3 ][ 2 ]; // 3nd entry in 4th column

			// we need different nearEstimate formula for reversed and default depth buffer
			// a is positive with a reversed depth buffer so it can be used for controlling the code flow
			float nearEstimate = ( a > 0.0 ) ? ( - b / ( a + 1.0 ) ) : ( - 0.5 * b / a );

			return ( nearEstimate - start.z ) / ( end.z - start.z );

		}

		void main() {

			#ifdef USE_COLOR

				vColor.xyz = ( position.y < 0.5 ) ? instanceColorStart : instanceColorEnd;

			#endif

			float aspect = resolution.x / resolution.y;

			// camera space
			vec4 start = modelViewMatrix * vec4( instanceStart, 1.0 );
			vec4 end = modelViewMatrix * vec4( instanceEnd, 1.0 );

			#ifdef USE_DASH

				float lineDistanceStart = dashScale * instanceDistanceStart;
				float lineDistanceEnd = dashScale * instanceDistanceEnd;

			#endif

			#ifdef WORLD_UNITS

				worldStart = start.xyz;
				worldEnd = end.xyz;

			#else

				vUv = uv;

			#endif

			// special case for perspective projection, and segments that terminate either in, or behind, the camera plane
			// clearly the gpu firmware has a way of addressing this issue when projecting into ndc space
			// but we need to perform ndc-space calculations in the shader, so we must address this issue directly
			// perhaps there is a more elegant solution -- WestLangley

			bool perspective = ( projectionMatrix[ 2 ][ 3 ] == - 1.0 ); // 4th entry in the 3rd column

			if ( perspective ) {

				if ( start.z < 0.0 && end.z >= 0.0 ) {

					float alpha = trimSegmentAlpha( start, end );
					end.xyz = mix( start.xyz, end.xyz, alpha );

					#ifdef USE_DASH

						lineDistanceEnd = mix( lineDistanceStart, lineDistanceEnd, alpha );

					#endif

				} else if ( end.z < 0.0 && start.z >= 0.0 ) {

					float alpha = trimSegmentAlpha( end, start );
					start.xyz = mix( end.xyz, start.xyz, alpha );

					#ifdef USE_DASH

						lineDistanceStart = mix( lineDistanceEnd, lineDistanceStart, alpha );

					#endif

				}

			}

			#ifdef USE_DASH

				vLineDistance = ( position.y < 0.5 ) ? lineDistanceStart : lineDistanceEnd;
				vUv = uv;

			#endif

			// clip space
			vec4 clipStart = projectionMatrix * start;
			vec4 clipEnd = projectionMatrix * end;

			// ndc space
			vec3 ndcStart = clipStart.xyz / clipStart.w;
			vec3 ndcEnd = clipEnd.xyz / clipEnd.w;

			// direction
			vec2 dir = ndcEnd.xy - ndcStart.xy;

			// account for clip-space aspect ratio
			dir.x *= aspect;
			dir = normalize( dir );

			#ifdef WORLD_UNITS

				vec3 worldDir = normalize( end.xyz - start.xyz );
				vec3 tmpFwd = perspective ? normalize( mix( start.xyz, end.xyz, 0.5 ) ) : vec3( 0.0, 0.0, - 1.0 );
				vec3 worldUp = normalize( cross( worldDir, tmpFwd ) );
				vec3 worldFwd = cross( worldDir, worldUp );
				worldPos = position.y < 0.5 ? start: end;

				// height offset
				float hw = linewidth * 0.5;
				worldPos.xyz += position.x < 0.0 ? hw * worldUp : - hw * worldUp;

				// don't extend the line if we're rendering dashes because we
				// won't be rendering the endcaps
				#ifndef USE_DASH

					// cap extension
					worldPos.xyz += position.y < 0.5 ? - hw * worldDir : hw * worldDir;

					// add width to the box
					worldPos.xyz += worldFwd * hw;

					// endcaps
					if ( position.y > 1.0 || position.y < 0.0 ) {

						worldPos.xyz -= worldFwd * 2.0 * hw;

					}

				#endif

				// project the worldpos
				vec4 clip = projectionMatrix * worldPos;

				// shift the depth of the projected points so the line
				// segments overlap neatly
				vec3 clipPose = ( position.y < 0.5 ) ? ndcStart : ndcEnd;

				// only shift the depth of vertices in front of the camera (#35137)
				if ( clip.w > 0.0 ) clip.z = clipPose.z * clip.w;

			#else

				vec2 offset = vec2( dir.y, - dir.x );
				// undo aspect ratio adjustment
				dir.x /= aspect;
				offset.x /= aspect;

				// sign flip
				if ( position.x < 0.0 ) offset *= - 1.0;

				// endcaps
				if ( position.y < 0.0 ) {

					offset += - dir;

				} else if ( position.y > 1.0 ) {

					offset += dir;

				}

				// adjust for linewidth
				offset *= linewidth;

				// adjust for clip-space to screen-space conversion // maybe resolution should be based on viewport ...
				offset /= resolution.y;

				// select end
				vec4 clip = ( position.y < 0.5 ) ? clipStart : clipEnd;

				// back to clip space
				offset *= clip.w;

				clip.xy += offset;

			#endif

			gl_Position = clip;

			vec4 mvPosition = ( position.y < 0.5 ) ? start : end; // this is an approximation

			#include <logdepthbuf_vertex>
			#include <clipping_planes_vertex>
			#include <fog_vertex>

		}
		`,fragmentShader:`
		uniform vec3 diffuse;
		uniform float opacity;
		uniform float linewidth;

		#ifdef USE_DASH

			uniform float dashOffset;
			uniform float dashSize;
			uniform float gapSize;

		#endif

		varying float vLineDistance;

		#ifdef WORLD_UNITS

			varying vec4 worldPos;
			varying vec3 worldStart;
			varying vec3 worldEnd;

			#ifdef USE_DASH

				varying vec2 vUv;

			#endif

		#else

			varying vec2 vUv;

		#endif

		#include <common>
		#include <color_pars_fragment>
		#include <fog_pars_fragment>
		#include <logdepthbuf_pars_fragment>
		#include <clipping_planes_pars_fragment>

		vec2 closestLineToLine(vec3 p1, vec3 p2, vec3 p3, vec3 p4) {

			float mua;
			float mub;

			vec3 p13 = p1 - p3;
			vec3 p43 = p4 - p3;

			vec3 p21 = p2 - p1;

			float d1343 = dot( p13, p43 );
			float d4321 = dot( p43, p21 );
			float d1321 = dot( p13, p21 );
			float d4343 = dot( p43, p43 );
			float d2121 = dot( p21, p21 );

			float denom = d2121 * d4343 - d4321 * d4321;

			float numer = d1343 * d4321 - d1321 * d4343;

			mua = numer / denom;
			mua = clamp( mua, 0.0, 1.0 );
			mub = ( d1343 + d4321 * ( mua ) ) / d4343;
			mub = clamp( mub, 0.0, 1.0 );

			return vec2( mua, mub );

		}

		void main() {

			float alpha = opacity;
			vec4 diffuseColor = vec4( diffuse, alpha );

			#include <clipping_planes_fragment>

			#ifdef USE_DASH

				if ( vUv.y < - 1.0 || vUv.y > 1.0 ) discard; // discard endcaps

				if ( mod( vLineDistance + dashOffset, dashSize + gapSize ) > dashSize ) discard; // todo - FIX

			#endif

			#ifdef WORLD_UNITS

				float len;

				if ( isOrthographic ) {

					// View rays are parallel to the z axis so the distance reduces to camera-space XY
					vec2 lineDir = worldEnd.xy - worldStart.xy;
					float t = clamp( dot( worldPos.xy - worldStart.xy, lineDir ) / dot( lineDir, lineDir ), 0.0, 1.0 );
					len = length( worldStart.xy + lineDir * t - worldPos.xy );

				} else {

					// Find the closest points on the view ray and the line segment
					vec3 rayEnd = normalize( worldPos.xyz ) * 1e5;
					vec3 lineDir = worldEnd - worldStart;
					vec2 params = closestLineToLine( worldStart, worldEnd, vec3( 0.0, 0.0, 0.0 ), rayEnd );

					vec3 p1 = worldStart + lineDir * params.x;
					vec3 p2 = rayEnd * params.y;
					vec3 delta = p1 - p2;
					len = length( delta );

				}

				float norm = len / linewidth;

				#ifndef USE_DASH

					#ifdef USE_ALPHA_TO_COVERAGE

						float dnorm = fwidth( norm );
						alpha = 1.0 - smoothstep( 0.5 - dnorm, 0.5 + dnorm, norm );

					#else

						if ( norm > 0.5 ) {

							discard;

						}

					#endif

				#endif

			#else

				#ifdef USE_ALPHA_TO_COVERAGE

					// artifacts appear on some hardware if a derivative is taken within a conditional
					float a = vUv.x;
					float b = ( vUv.y > 0.0 ) ? vUv.y - 1.0 : vUv.y + 1.0;
					float len2 = a * a + b * b;
					float dlen = fwidth( len2 );

					if ( abs( vUv.y ) > 1.0 ) {

						alpha = 1.0 - smoothstep( 1.0 - dlen, 1.0 + dlen, len2 );

					}

				#else

					if ( abs( vUv.y ) > 1.0 ) {

						float a = vUv.x;
						float b = ( vUv.y > 0.0 ) ? vUv.y - 1.0 : vUv.y + 1.0;
						float len2 = a * a + b * b;

						if ( len2 > 1.0 ) discard;

					}

				#endif

			#endif

			#include <logdepthbuf_fragment>
			#include <color_fragment>

			gl_FragColor = vec4( diffuseColor.rgb, alpha );

			#include <tonemapping_fragment>
			#include <colorspace_fragment>
			#include <fog_fragment>
			#include <premultiplied_alpha_fragment>

		}
		`};bs=class extends Bn{constructor(t){super({type:"LineMaterial",uniforms:Br.clone(xn.line.uniforms),vertexShader:xn.line.vertexShader,fragmentShader:xn.line.fragmentShader,clipping:!0}),this.isLineMaterial=!0,this.setValues(t)}get color(){return this.uniforms.diffuse.value}set color(t){this.uniforms.diffuse.value=t}get worldUnits(){return"WORLD_UNITS"in this.defines}set worldUnits(t){t===!0!==this.worldUnits&&(this.needsUpdate=!0),t===!0?this.defines.WORLD_UNITS="":delete this.defines.WORLD_UNITS}get linewidth(){return this.uniforms.linewidth.value}set linewidth(t){this.uniforms.linewidth&&(this.uniforms.linewidth.value=t)}get dashed(){return"USE_DASH"in this.defines}set dashed(t){t===!0!==this.dashed&&(this.needsUpdate=!0),t===!0?this.defines.USE_DASH="":delete this.defines.USE_DASH}get dashScale(){return this.uniforms.dashScale.value}set dashScale(t){this.uniforms.dashScale.value=t}get dashSize(){return this.uniforms.dashSize.value}set dashSize(t){this.uniforms.dashSize.value=t}get dashOffset(){return this.uniforms.dashOffset.value}set dashOffset(t){this.uniforms.dashOffset.value=t}get gapSize(){return this.uniforms.gapSize.value}set gapSize(t){this.uniforms.gapSize.value=t}get opacity(){return this.uniforms.opacity.value}set opacity(t){this.uniforms&&(this.uniforms.opacity.value=t)}get resolution(){return this.uniforms.resolution.value}set resolution(t){this.uniforms.resolution.value.copy(t)}get alphaToCoverage(){return"USE_ALPHA_TO_COVERAGE"in this.defines}set alphaToCoverage(t){this.defines&&(t===!0!==this.alphaToCoverage&&(this.needsUpdate=!0),t===!0?this.defines.USE_ALPHA_TO_COVERAGE="":delete this.defines.USE_ALPHA_TO_COVERAGE)}}});var wp,cl,xs,Ad=ha(()=>{gs();wp=new Oe,cl=new z,xs=class extends Sr{constructor(){super(),this.isLineSegmentsGeometry=!0,this.type="LineSegmentsGeometry";let t=[-1,2,0,1,2,0,-1,1,0,1,1,0,-1,0,0,1,0,0,-1,-1,0,1,-1,0],e=[-1,2,1,2,-1,1,1,1,-1,-1,1,-1,-1,-2,1,-2],n=[0,2,1,2,3,1,2,4,3,4,5,3,4,6,5,6,7,5];this.setIndex(n),this.setAttribute("position",new xe(t,3)),this.setAttribute("uv",new xe(e,2))}applyMatrix4(t){let e=this.attributes.instanceStart,n=this.attributes.instanceEnd;return e!==void 0&&(e.applyMatrix4(t),n.applyMatrix4(t),e.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this}setPositions(t){let e;t instanceof Float32Array?e=t:Array.isArray(t)&&(e=new Float32Array(t));let n=new Xi(e,6,1);return this.setAttribute("instanceStart",new Jn(n,3,0)),this.setAttribute("instanceEnd",new Jn(n,3,3)),this.instanceCount=this.attributes.instanceStart.count,this.computeBoundingBox(),this.computeBoundingSphere(),this}setColors(t){let e;t instanceof Float32Array?e=t:Array.isArray(t)&&(e=new Float32Array(t));let n=new Xi(e,6,1);return this.setAttribute("instanceColorStart",new Jn(n,3,0)),this.setAttribute("instanceColorEnd",new Jn(n,3,3)),this}fromWireframeGeometry(t){return this.setPositions(t.attributes.position.array),this}fromEdgesGeometry(t){return this.setPositions(t.attributes.position.array),this}fromMesh(t){return this.fromWireframeGeometry(new mr(t.geometry)),this}fromLineSegments(t){let e=t.geometry;return this.setPositions(e.attributes.position.array),this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Oe);let t=this.attributes.instanceStart,e=this.attributes.instanceEnd;t!==void 0&&e!==void 0&&(this.boundingBox.setFromBufferAttribute(t),wp.setFromBufferAttribute(e),this.boundingBox.union(wp))}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new Ge),this.boundingBox===null&&this.computeBoundingBox();let t=this.attributes.instanceStart,e=this.attributes.instanceEnd;if(t!==void 0&&e!==void 0){let n=this.boundingSphere.center;this.boundingBox.getCenter(n);let a=0;for(let s=0,r=t.count;s<r;s++)cl.fromBufferAttribute(t,s),a=Math.max(a,n.distanceToSquared(cl)),cl.fromBufferAttribute(e,s),a=Math.max(a,n.distanceToSquared(cl));this.boundingSphere.radius=Math.sqrt(a),isNaN(this.boundingSphere.radius)&&console.error("THREE.LineSegmentsGeometry.computeBoundingSphere(): Computed radius is NaN. The instanced position data is likely to have NaN values.",this)}}toJSON(){}}});function Ip(i,t,e){return fi.set(0,0,-t,1).applyMatrix4(i.projectionMatrix),fi.multiplyScalar(1/fi.w),fi.x=Ea/e.width,fi.y=Ea/e.height,fi.applyMatrix4(i.projectionMatrixInverse),fi.multiplyScalar(1/fi.w),Math.abs(Math.max(fi.x,fi.y))}function wv(i,t){let e=i.matrixWorld,n=i.geometry,a=n.attributes.instanceStart,s=n.attributes.instanceEnd,r=Math.min(n.instanceCount,a.count);for(let o=0,c=r;o<c;o++){Ye.start.fromBufferAttribute(a,o),Ye.end.fromBufferAttribute(s,o),Ye.applyMatrix4(e);let l=new z,h=new z;pi.distanceSqToSegment(Ye.start,Ye.end,h,l),h.distanceTo(l)<Ea*.5&&t.push({point:h,pointOnLine:l,distance:pi.origin.distanceTo(h),object:i,face:null,faceIndex:o,uv:null,uv1:null})}}function Av(i,t,e){let n=t.projectionMatrix,s=i.material.resolution,r=i.matrixWorld,o=i.geometry,c=o.attributes.instanceStart,l=o.attributes.instanceEnd,h=Math.min(o.instanceCount,c.count),u=-t.near;pi.at(1,ui),ui.w=1,ui.applyMatrix4(t.matrixWorldInverse),ui.applyMatrix4(n),ui.multiplyScalar(1/ui.w),ui.x*=s.x/2,ui.y*=s.y/2,ui.z=0,Td.copy(ui),Id.multiplyMatrices(t.matrixWorldInverse,r);for(let d=0,f=h;d<f;d++){if(Xe.fromBufferAttribute(c,d),qe.fromBufferAttribute(l,d),Xe.w=1,qe.w=1,Xe.applyMatrix4(Id),qe.applyMatrix4(Id),Xe.z>u&&qe.z>u)continue;if(Xe.z>u){let w=Xe.z-qe.z,p=(Xe.z-u)/w;Xe.lerp(qe,p)}else if(qe.z>u){let w=qe.z-Xe.z,p=(qe.z-u)/w;qe.lerp(Xe,p)}Xe.applyMatrix4(n),qe.applyMatrix4(n),Xe.multiplyScalar(1/Xe.w),qe.multiplyScalar(1/qe.w),Xe.x*=s.x/2,Xe.y*=s.y/2,qe.x*=s.x/2,qe.y*=s.y/2,Ye.start.copy(Xe),Ye.start.z=0,Ye.end.copy(qe),Ye.end.z=0;let v=Ye.closestPointToPointParameter(Td,!0);Ye.at(v,Tp);let m=wa.lerp(Xe.z,qe.z,v),g=m>=-1&&m<=1,y=Td.distanceTo(Tp)<Ea*.5;if(g&&y){Ye.start.fromBufferAttribute(c,d),Ye.end.fromBufferAttribute(l,d),Ye.start.applyMatrix4(r),Ye.end.applyMatrix4(r);let w=new z,p=new z;pi.distanceSqToSegment(Ye.start,Ye.end,p,w),e.push({point:p,pointOnLine:w,distance:pi.origin.distanceTo(p),object:i,face:null,faceIndex:d,uv:null,uv1:null})}}}var Ed,Ap,Ep,Xe,qe,ui,Td,Id,Ye,Tp,ll,hl,fi,pi,Ea,dl,Rp=ha(()=>{gs();Ad();wd();Ed=new ce,Ap=new z,Ep=new z,Xe=new ce,qe=new ce,ui=new ce,Td=new z,Id=new oe,Ye=new xa,Tp=new z,ll=new Oe,hl=new Ge,fi=new ce;dl=class extends nn{constructor(t=new xs,e=new bs({color:Math.random()*16777215})){super(t,e),this.isLineSegments2=!0,this.type="LineSegments2"}computeLineDistances(){let t=this.geometry,e=t.attributes.instanceStart,n=t.attributes.instanceEnd,a=new Float32Array(2*e.count);for(let r=0,o=0,c=e.count;r<c;r++,o+=2)Ap.fromBufferAttribute(e,r),Ep.fromBufferAttribute(n,r),a[o]=o===0?0:a[o-1],a[o+1]=a[o]+Ap.distanceTo(Ep);let s=new Xi(a,2,1);return t.setAttribute("instanceDistanceStart",new Jn(s,1,0)),t.setAttribute("instanceDistanceEnd",new Jn(s,1,1)),this}raycast(t,e){let n=this.material.worldUnits,a=t.camera;if(a===null&&!n&&console.error('LineSegments2: "Raycaster.camera" needs to be set in order to raycast against LineSegments2 while worldUnits is set to false.'),n===!1&&(this.material.resolution.x===0||this.material.resolution.y===0))return;let s=t.params.Line2!==void 0&&t.params.Line2.threshold||0;pi=t.ray;let r=this.matrixWorld,o=this.geometry,c=this.material;Ea=c.linewidth+s,o.boundingSphere===null&&o.computeBoundingSphere(),hl.copy(o.boundingSphere).applyMatrix4(r);let l;if(n)l=Ea*.5;else{let u=Math.max(a.near,hl.distanceToPoint(pi.origin));l=Ip(a,u,c.resolution)}if(hl.radius+=l,pi.intersectsSphere(hl)===!1)return;o.boundingBox===null&&o.computeBoundingBox(),ll.copy(o.boundingBox).applyMatrix4(r);let h;if(n)h=Ea*.5;else{let u=Math.max(a.near,ll.distanceToPoint(pi.origin));h=Ip(a,u,c.resolution)}ll.expandByScalar(h),pi.intersectsBox(ll)!==!1&&(n?wv(this,e):Av(this,a,e))}onBeforeRender(t){let e=this.material.uniforms;e&&e.resolution&&(t.getViewport(Ed),this.material.uniforms.resolution.value.set(Ed.z,Ed.w))}}});var ys={};xu(ys,{AmbientLight:()=>Mr,BackSide:()=>je,BatchedMesh:()=>sr,Box3:()=>Oe,BufferAttribute:()=>pn,BufferGeometry:()=>Ue,ByteType:()=>Rr,Color:()=>jt,ConeGeometry:()=>dr,CylinderGeometry:()=>ss,DataTexture:()=>Ei,DirectionalLight:()=>vr,DoubleSide:()=>kn,FloatType:()=>gn,FrontSide:()=>ci,GridHelper:()=>Ar,Group:()=>wi,IntType:()=>ds,Line:()=>ba,Line3:()=>xa,LineBasicMaterial:()=>ga,LineLoop:()=>rr,LineMaterial:()=>bs,LineSegments:()=>is,LineSegments2:()=>dl,LineSegmentsGeometry:()=>xs,MathUtils:()=>wa,Matrix3:()=>Vt,Matrix4:()=>oe,Mesh:()=>nn,MeshBasicMaterial:()=>ns,MeshLambertMaterial:()=>gr,NearestFilter:()=>De,Object3D:()=>Fe,OrbitControls:()=>ol,PerspectiveCamera:()=>fn,Plane:()=>un,Points:()=>or,REVISION:()=>mc,RGBAFormat:()=>bn,RGBAIntegerFormat:()=>fs,RGFormat:()=>hi,RGIntegerFormat:()=>us,Ray:()=>Kn,Raycaster:()=>wr,RedFormat:()=>Nr,RedIntegerFormat:()=>Sa,Scene:()=>er,ShortType:()=>Cr,Sphere:()=>Ge,SphereGeometry:()=>fr,TOUCH:()=>oi,TorusGeometry:()=>pr,Triangle:()=>ai,UnsignedByteType:()=>an,UnsignedIntType:()=>An,UnsignedShortType:()=>Yi,Vector2:()=>Bt,Vector3:()=>z,Vector4:()=>ce,WebGLRenderer:()=>il});var _s=ha(()=>{gs();Sp();wd();Rp();Ad()});var BM={};xu(BM,{default:()=>FM,explorer:()=>Dd,mesh:()=>ou});var Cp=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),Ev=globalThis[Cp]||(globalThis[Cp]=(_s(),Pa(ys))),{AmbientLight:Np,BackSide:ul,BatchedMesh:bE,Box3:rn,BufferAttribute:on,BufferGeometry:Ki,ByteType:xE,Color:mi,ConeGeometry:Pp,CylinderGeometry:Lp,DataTexture:yE,DirectionalLight:Dp,DoubleSide:Zi,FloatType:_E,FrontSide:Di,GridHelper:Up,Group:fl,IntType:vE,Line:ME,Line3:zn,LineBasicMaterial:vs,LineLoop:SE,LineSegments:Rd,MathUtils:wE,Matrix3:AE,Matrix4:Je,Mesh:yn,MeshBasicMaterial:Op,MeshLambertMaterial:Fp,NearestFilter:EE,Object3D:TE,PerspectiveCamera:Bp,Plane:Ms,Points:IE,REVISION:Cd,RGBAFormat:RE,RGBAIntegerFormat:CE,RGFormat:NE,RGIntegerFormat:PE,Ray:kp,Raycaster:pl,RedFormat:LE,RedIntegerFormat:DE,Scene:zp,ShortType:UE,Sphere:OE,SphereGeometry:Vp,TOUCH:Hp,TorusGeometry:Gp,Triangle:Ui,UnsignedByteType:FE,UnsignedIntType:BE,UnsignedShortType:kE,Vector2:cn,Vector3:rt,Vector4:zE,WebGLRenderer:Wp}=Ev;var Nd=new rt(0,1,0),Pd=new rt,ml=class i{constructor(t){this.root=new fl,t.add(this.root),this.owned=[],this.materials={},this.cylinder=this.own(new Lp(1,1,1,18,1).translate(0,.5,0)),this.cone=this.own(new Pp(1,1,24,1).translate(0,.5,0)),this.sphere=this.own(new Vp(1,28,18)),this.triGeometry=this.own(new Ki),this.triGeometry.setAttribute("position",new on(new Float32Array(9),3)),this.front=this.add(new yn(this.triGeometry,this.material("front",{side:Di,offset:!0}))),this.back=this.add(new yn(this.triGeometry,this.material("back",{side:ul,offset:!0}))),this.paraGeometry=this.own(new Ki),this.paraGeometry.setAttribute("position",new on(new Float32Array(18),3)),this.para=this.add(new yn(this.paraGeometry,this.material("para",{side:Zi,opacity:.28}))),this.paraEdges=[this.stick("paraEdge"),this.stick("paraEdge")],this.edges=[this.stick("edge"),this.stick("edge"),this.stick("edge")],this.ring=[0,1,2].map(()=>this.add(new yn(this.cone,this.material("ring")))),this.vertices={};for(let e of"ABC")this.vertices[e]=this.add(new yn(this.sphere,this.material(e)));this.u=this.arrow("U"),this.v=this.arrow("V"),this.n=this.arrow("N"),this.unit=this.arrow("unit",{opacity:.45}),this.cue=new fl,this.root.add(this.cue),this.cueArc=new yn(void 0,this.material("N")),this.cueHead=new yn(this.cone,this.material("N")),this.cueHead.rotation.z=-Math.PI/2,this.cue.add(this.cueArc,this.cueHead),this.cueArcAngle=null,this.arcs=new Map,this.line=this.stick("line"),this.axes={};for(let e of"xyz")this.axes[e]={arrow:this.arrow(e),ticks:[]};this.grid=null}own(t){return this.owned.push(t),t}add(t){return this.root.add(t),t}material(t,{side:e=Di,opacity:n=1,offset:a=!1}={}){let s=t+":"+e+":"+n+":"+a;if(!this.materials[s]){let r=new Op({side:e,transparent:n<1,opacity:n,depthWrite:n>=1});a&&Object.assign(r,{polygonOffset:!0,polygonOffsetFactor:1,polygonOffsetUnits:1}),r.userData.role=t,this.materials[s]=r}return this.materials[s]}paint(t){for(let e of Object.values(this.materials))e.color.set(t(e.userData.role))}arrow(t,e={}){let n=new fl,a=new yn(this.cylinder,this.material(t,e)),s=new yn(this.cone,this.material(t,e));return n.add(a,s),this.root.add(n),{group:n,shaft:a,head:s}}stick(t){return this.add(new yn(this.cylinder,this.material(t)))}static placeStick(t,e,n,a){Pd.subVectors(n,e);let s=Pd.length();t.visible=s>0,s&&(t.position.copy(e),t.quaternion.setFromUnitVectors(Nd,Pd.divideScalar(s)),t.scale.set(a,s,a))}static placeArrow(t,e,n,a,s=!0){let r=new rt().subVectors(n,e),o=r.length();if(t.group.visible=s&&o>0,!t.group.visible)return;let c=Math.min(7*a,.45*o),l=Math.min(2.6*a,c*.5);t.group.position.copy(e),t.group.quaternion.setFromUnitVectors(Nd,r.divideScalar(o)),t.shaft.scale.set(a,o-c*.9,a),t.head.position.set(0,o-c,0),t.head.scale.set(l,c,l)}setAxes(t,e,n,a,s){let r=[];for(let o of"xyz"){let c=new rt(o==="x"?1:0,o==="y"?1:0,o==="z"?1:0),l=this.axes[o];i.placeArrow(l.arrow,c.clone().multiplyScalar(-t),c.clone().multiplyScalar(t),n,s);let h=s?Math.floor(t/e+1e-9):0;for(;l.ticks.length<2*h;)l.ticks.push(this.add(new yn(this.sphere,this.material(o))));l.ticks.forEach((u,d)=>{let f=d<h?d+1:-(d-h+1);u.visible=d<2*h&&Math.abs(f*e)<t-1e-9,u.position.copy(c).multiplyScalar(f*e),u.scale.setScalar(n*1.9),u.visible&&f>0&&r.push({axis:o,value:f*e,position:u.position.clone()})})}return r}setGrid(t,e,n,a){if(this.grid&&(this.root.remove(this.grid),this.grid.geometry.dispose(),this.grid.material.dispose(),this.grid=null),!a)return;let s=Math.max(2,Math.round(4*t/e));this.grid=new Up(2*t,s,n.gridMajor,n.grid),this.grid.rotation.x=Math.PI/2,this.grid.material.depthWrite=!1,this.grid.renderOrder=-1,this.root.add(this.grid)}update(t){let{A:e,P:n,Q:a,centroid:s,r}=t,o=this.triGeometry.attributes.position;[e,n,a].forEach((h,u)=>o.setXYZ(u,h.x,h.y,h.z)),o.needsUpdate=!0,this.triGeometry.computeBoundingSphere(),this.front.visible=this.back.visible=!t.degenerate;for(let h of"ABC"){let u=this.vertices[h];u.position.copy(t[h]),u.scale.setScalar(r*(t.degenerate?3.4:2.5))}let c=[e,n,a];for(let h=0;h<3;h++){let u=c[h],d=c[(h+1)%3];i.placeStick(this.edges[h],u,d,r*.45);let f=this.ring[h],x=new rt().subVectors(d,u),v=x.length();if(f.visible=!t.degenerate&&v>0,f.visible){let m=Math.min(4.5*r,.22*v),g=new rt().addVectors(u,d).multiplyScalar(.5).lerp(s,.22);f.quaternion.setFromUnitVectors(Nd,x.divideScalar(v)),f.position.copy(g).addScaledVector(x,-m/2),f.scale.set(m*.45,m,m*.45)}}i.placeArrow(this.u,e,n,r),i.placeArrow(this.v,e,a,r);let l=s.clone().add(t.nDraw);i.placeArrow(this.n,s,l,r*1.15,!t.degenerate),i.placeArrow(this.unit,s,t.unitDraw?s.clone().add(t.unitDraw):s,r*1.9,!t.degenerate&&!!t.unitDraw),this.updateCue(t),this.updateParallelogram(t),this.updateLine(t)}updateCue(t){let e=t.nDraw.clone(),n=e.length();if(t.degenerate||!n){this.cue.visible=!1;return}e.divideScalar(n);let a=new rt().subVectors(t.P,t.A),s=new rt().subVectors(t.Q,t.A),r=a.clone().addScaledVector(e,-a.dot(e)).normalize(),o=new rt().crossVectors(e,r),c=Math.atan2(s.dot(o),s.dot(r));c>0||(c=Math.PI/2),c=Math.max(c,.45*Math.PI);let l=Math.PI/36,h=Math.round(c/l);this.arcs.has(h)||this.arcs.set(h,new Gp(1,.055,8,48,h*l)),this.cueArc.geometry=this.arcs.get(h),this.cueArcAngle=h*l;let u=this.cueArcAngle;this.cueHead.position.set(Math.cos(u),Math.sin(u),0),this.cueHead.rotation.set(0,0,u),this.cueHead.position.addScaledVector(new rt(-Math.sin(u),Math.cos(u),0),-.12),this.cueHead.scale.set(.16,.32,.16);let d=.32*Math.min(a.length(),s.length(),1.2*n)+1e-9,f=new Je().makeBasis(r,o,e);this.cue.quaternion.setFromRotationMatrix(f),this.cue.position.copy(t.centroid).addScaledVector(e,.3*n),this.cue.scale.setScalar(Math.max(d,3*t.r)),this.cue.visible=!0}updateParallelogram(t){let e=t.showParallelogram&&!t.degenerate;if(this.para.visible=e,this.paraEdges.forEach(s=>s.visible=e),!e)return;let n=new rt().addVectors(t.P,t.Q).sub(t.A),a=this.paraGeometry.attributes.position;[t.P,n,t.Q,t.P,n,t.Q].forEach((s,r)=>a.setXYZ(r,s.x,s.y,s.z)),a.needsUpdate=!0,this.paraGeometry.computeBoundingSphere(),i.placeStick(this.paraEdges[0],t.P,n,t.r*.45),i.placeStick(this.paraEdges[1],t.Q,n,t.r*.45),t.D=n}updateLine(t){if(this.line.visible=!1,!t.degenerate)return;let e=[t.A,t.B,t.C],n=null,a=0;for(let l=0;l<3;l++)for(let h=l+1;h<3;h++){let u=e[l].distanceTo(e[h]);u>a&&([a,n]=[u,[e[l],e[h]]])}if(!n||a<t.r)return;let s=new rt().subVectors(n[1],n[0]).normalize(),r=Math.max(.35*a,6*t.r),o=n[0].clone().addScaledVector(s,-r),c=n[1].clone().addScaledVector(s,r);i.placeStick(this.line,o,c,t.r*.9)}pickables(){return Object.entries(this.vertices).map(([t,e])=>({name:t,mesh:e}))}dispose(){this.setGrid(0,1,null,!1);for(let t of this.arcs.values())t.dispose();for(let t of this.owned)t.dispose();for(let t of Object.values(this.materials))t.dispose();this.root.removeFromParent()}};var Tv=/^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$/,Iv=/^([+-]?\d+)\s*\/\s*([+-]?\d+)$/;function Qi(i){let t=String(i??"").trim();if(Tv.test(t))return Number(t);let e=Iv.exec(t);if(e){let n=Number(e[1])/Number(e[2]);return Number.isFinite(n)?n:NaN}return NaN}function jp(i){if(!Array.isArray(i)||i.length!==3)return null;let t=i.map(Qi);return t.every(Number.isFinite)?t:null}function Gr(i){let t=String(i??"0.1").trim(),e=/^(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?$/.exec(t);if(!e||!(Number(t)>0)||!/\d/.test((e[1]||"")+(e[2]||"")))return{value:.1,decimals:1,units:1};let n=((e[1]||"")+(e[2]||"")).replace(/^0+(?=\d)/,""),a=Number(e[3]||0)-(e[2]||"").length;for(;n.length>1&&n.endsWith("0");)n=n.slice(0,-1),a+=1;let s=Math.max(0,-a),r=Number(n)*10**(a+s);return{value:r/10**s,decimals:s,units:r}}function Rv(i){let t=new DataView(new ArrayBuffer(8));t.setFloat64(0,i);let e=t.getBigUint64(0),n=e>>63n===1n,a=Number(e>>52n&0x7ffn),s=e&(1n<<52n)-1n;a&&(s|=1n<<52n);let r=(a||1)-1075,o=n?-s:s;return r>=0?[o<<BigInt(r),1n]:[o,1n<<BigInt(-r)]}function Cv(i,t){if(!Number.isFinite(i))return 0;let[e,n]=Rv(i),a=10n**BigInt(t.decimals),s=BigInt(t.units),o=((e<0n?-e:e)*a*2n+n*s)/(2n*n*s);return Number(e<0n?-o:o)}function Wr(i,t,e){let n=Cv(i,t);if(Array.isArray(e)&&e.length===2){let a=Math.ceil(Number(e[0])/t.value-1e-9),s=Math.floor(Number(e[1])/t.value+1e-9);Number.isFinite(a)&&(n=Math.max(n,a)),Number.isFinite(s)&&(n=Math.min(n,s))}return n===0?0:n}function Ld(i,t,e){return Math.abs(i-t*e.value)<=1e-9*Math.max(1,Math.abs(i))}function jr(i,t){let e=BigInt(i)*BigInt(t.units),n=e<0n,a=(n?-e:e).toString();return t.decimals>0&&(a=a.padStart(t.decimals+1,"0"),a=a.slice(0,-t.decimals)+"."+a.slice(-t.decimals)),(n?"-":"")+a}function Xp(i){return!(i>0)||!Number.isFinite(i)?1:10**Math.floor(Math.log10(i))}function qp(i){if(!(i>0))return 1;let t=10**Math.floor(Math.log10(i));for(let e of[1,2,5,10])if(e*t>=i*(1-1e-9))return e*t;return 10*t}function Yp(i){if(i===0)return"0";let t=Math.abs(i);return t>=1e5||t<.001?i.toExponential(0).replace("e+","e"):String(Number(i.toPrecision(6)))}var Nv=22,Jp=(i,t)=>i.toLowerCase()+"xyz"[t],Kp={ArrowRight:[0,1],ArrowLeft:[0,-1],ArrowUp:[1,1],ArrowDown:[1,-1],PageUp:[2,1],PageDown:[2,-1]};function Zp(i){let t=new pl,e=new cn,n=new Ms,a=null,s=null,r=0;function o(p,_){let S=i.canvas.getBoundingClientRect();return e.set((p-S.left)/S.width*2-1,-((_-S.top)/S.height)*2+1),t.setFromCamera(e,i.camera),t.ray}function c(p,_){return o(p,_).intersectPlane(n,new rt)}function l(p,_){let S=i.canvas.getBoundingClientRect(),b=null,M=Nv;for(let E of"ABC"){let A=i.position(E);if(!A)continue;let I=A.clone().project(i.camera),N=S.left+(I.x+1)/2*S.width,L=S.top+(1-I.y)/2*S.height,P=Math.hypot(N-p,L-_);P<M&&([b,M]=[E,P])}return b}function h(p,_){let S=i.position(p);if(!S)return!1;let b=i.camera.getWorldDirection(new rt);n.setFromNormalAndCoplanarPoint(b,S);let M=c(_.clientX,_.clientY);if(!M)return!1;let E=i.values(p).slice();return a={name:p,pointerId:_.pointerId,hit:M,strings:E,moved:new Set,start:E.map((A,I)=>{let N=Qi(A);return Number.isFinite(N)?N:S.getComponent(I)*i.scale()})},i.container.setPointerCapture(_.pointerId),i.container.classList.add("tnx-dragging"),i.dragging(!0,p),!0}function u(){if(r=0,!a||!s)return;let p=c(s.clientX,s.clientY);if(s=null,!p)return;let _=p.sub(a.hit).multiplyScalar(i.scale()),S=i.grid(),b=i.values(a.name),M={};a.strings.forEach((E,A)=>{let I=E,N=_.getComponent(A);if(Math.abs(N)>=S.value/2){let L=Wr(a.start[A]+N,S,i.bounds());Ld(a.start[A],L,S)||(I=jr(L,S))}I!==E&&a.moved.add(A),a.moved.has(A)&&I!==b[A]&&(M[Jp(a.name,A)]=I)}),Object.keys(M).length&&i.write(M)}function d(p){if(a||p.button>0||p.pointerType==="touch"&&i.touchActive&&!i.touchActive())return;let _=p.target.closest?.("[data-vertex]"),S=_?_.dataset.vertex:p.target===i.canvas?l(p.clientX,p.clientY):null;S&&h(S,p)&&(p.preventDefault(),p.stopPropagation(),_&&_.focus({preventScroll:!0}))}function f(p){if(!a){p.target===i.canvas&&p.buttons===0&&(i.canvas.style.cursor=l(p.clientX,p.clientY)?"grab":"");return}p.pointerId===a.pointerId&&(p.preventDefault(),s={clientX:p.clientX,clientY:p.clientY},r||(r=requestAnimationFrame(u)))}function x(p){let _=a.name;a=null,s=null,i.container.classList.remove("tnx-dragging"),i.container.hasPointerCapture?.(p)&&i.container.releasePointerCapture(p),i.dragging(!1,_)}function v(p){!a||p.pointerId!==a.pointerId||(s&&(cancelAnimationFrame(r),r=0,p.type!=="pointercancel"&&u()),x(p.pointerId))}function m(){a&&(r&&cancelAnimationFrame(r),r=0,x(a.pointerId))}function g(p){let _=p.target.closest?.("[data-vertex]");if(!_||!(p.key in Kp)||p.altKey||p.ctrlKey||p.metaKey)return;p.preventDefault();let S=_.dataset.vertex,[b,M]=Kp[p.key],E=i.values(S)[b],A=i.grid(),I=Qi(E);Number.isFinite(I)||(I=(i.position(S)?.getComponent(b)??0)*i.scale());let N=Wr(I+M*A.value,A,i.bounds());if(Ld(I,N,A))return;let L=jr(N,A);L!==E&&i.write({[Jp(S,b)]:L})}let y=i.container;y.addEventListener("pointerdown",d,{capture:!0}),y.addEventListener("pointermove",f),y.addEventListener("pointerup",v),y.addEventListener("pointercancel",v),y.addEventListener("keydown",g);let w=()=>{r&&cancelAnimationFrame(r),y.removeEventListener("pointerdown",d,{capture:!0}),y.removeEventListener("pointermove",f),y.removeEventListener("pointerup",v),y.removeEventListener("pointercancel",v),y.removeEventListener("keydown",g)};return w.cancel=m,w}function $i(i,t){let e=String(t);i.textContent!==e&&(i.textContent=e)}function _n(i,t,e){let n=String(e);i.getAttribute(t)!==n&&i.setAttribute(t,n)}function Vn(i,t){i.hidden!==!!t&&(i.hidden=!!t)}var Qp=new WeakMap;function Ta(i,t,e){let n=Qp.get(i);n||Qp.set(i,n={}),n[t]!==e&&(n[t]=e,i.style[t]=e)}var Xr=new rt;function $p(i,t,e){return Xr.copy(i).project(t),{x:(Xr.x+1)/2*e.width,y:(1-Xr.y)/2*e.height,behind:Xr.z>1||Xr.z<-1}}var gl=class{constructor(t){this.el=document.createElement("div"),this.el.className="tnx-labels",t.appendChild(this.el),this.items=new Map}label(t,e,n){let a=this.items.get(t);if(!a){let s=document.createElement("div");s.className="tnx-label tnx-"+e,this.el.appendChild(s),a={el:s,kind:e,anchor:null,away:null,offset:0,visible:!0,text:null},this.items.set(t,a)}return n!==void 0&&a.text!==n&&(a.el.textContent=n,a.text=n,a.half=null),a}place(t,e,{away:n=null,offset:a=0,angle:s=null,visible:r=!0}={}){let o=this.items.get(t);o&&(o.anchor=e?e.clone():null,o.away=n?n.clone():null,o.offset=a,o.angle=s,o.visible=r&&!!e)}hide(t){for(let[e,n]of this.items)e.startsWith(t)&&(n.visible=!1)}layout(t,e){let n=[];for(let a of this.items.values()){if(!a.visible||!a.anchor){Vn(a.el,!0);continue}let s=$p(a.anchor,t,e);if(s.behind){Vn(a.el,!0);continue}let r=0,o=0;if(a.offset){let h=0,u=0;if(a.away){let f=$p(a.away,t,e);h=s.x-f.x,u=s.y-f.y}let d=Math.hypot(h,u);d<8&&a.angle!==null?(h=Math.cos(a.angle),u=-Math.sin(a.angle)):d<1e-6?(h=0,u=-1):(h/=d,u/=d),r=h*a.offset,o=u*a.offset}let c=s.x+r,l=s.y+o;if(a.kind==="vertex"){for(let h of n)Math.hypot(h.x-c,h.y-l)<30&&a.angle!==null&&(c=s.x+Math.cos(a.angle)*a.offset*1.4,l=s.y-Math.sin(a.angle)*a.offset*1.4);c=Math.min(Math.max(c,20),e.width-20),l=Math.min(Math.max(l,20),e.height-20),n.push({x:c,y:l})}if(Vn(a.el,!1),a.kind==="arrow"){(!a.half||!a.half.w)&&(a.half={w:a.el.offsetWidth/2,h:a.el.offsetHeight/2});let{w:h,h:u}=a.half;e.width>2*h+4&&(c=Math.min(Math.max(c,h+2),e.width-h-2)),e.height>2*u+4&&(l=Math.min(Math.max(l,u+2),e.height-u-2))}a.el.style.transform=`translate(${c.toFixed(1)}px, ${l.toFixed(1)}px) translate(-50%, -50%)`}}dispose(){this.el.remove(),this.items.clear()}};function Qn(i,t,e){let n=document.createElement(i);return(i==="input"||i==="select")&&(n.dataset.lmSuppressShortcuts="true"),t&&(n.className=t),e!==void 0&&(n.textContent=e),n}function tm(i,t){let e=Qn("div","tnx-controls");e.setAttribute("role","group"),e.setAttribute("aria-label","Coordinates");let n={};for(let c of"abc"){let l=Qn("div","tnx-vertex-row"),h=Qn("span","tnx-vertex-name",c.toUpperCase()),u=Qn("span","tnx-coords");l.append(h,u),n[c]={name:h,cells:[]},["x","y","z"].forEach((d,f)=>{let x=Qn("span","tnx-coord"),v=Qn("input","tnx-slider");v.type="range",v.setAttribute("aria-label",`${c.toUpperCase()}.${d} slider`);let m=Qn("input","tnx-exact");m.type="text",m.spellcheck=!1,m.autocomplete="off",m.setAttribute("aria-label",`${c.toUpperCase()}.${d}, exact value: type a number such as 0.1, -2 or 1/3 and press Enter`),m.title=`${c.toUpperCase()}.${d}: type a number such as 0.1, -2 or 1/3 and press Enter`,x.append(Qn("span","tnx-axis-name",d),v,m),u.appendChild(x),n[c].cells.push({slider:v,box:m});let g=0;v.addEventListener("input",()=>{g||(g=requestAnimationFrame(()=>{g=0;let w=Gr(t.get("step")),p=Wr(Number(v.value),w,t.get("bounds")),_=jr(p,w);String((t.get(c)||[])[f]??"")!==_&&(m.value=_,t.edit({[c+d]:_}))}))}),m.addEventListener("input",()=>{m.dataset.dirty="true"});let y=()=>{m.dataset.dirty&&(delete m.dataset.dirty,t.edit({[c+d]:m.value}))};m.addEventListener("change",y),m.addEventListener("keydown",w=>{w.key==="Enter"?y():w.key==="Escape"&&(delete m.dataset.dirty,m.value=String((t.get(c)||[])[f]??""))})}),e.appendChild(l)}let a=Qn("div","tnx-settings"),s=Qn("label","tnx-decimals","decimals "),r=Qn("select");s.appendChild(r),r.addEventListener("change",()=>t.edit({precision:Number(r.value)})),a.appendChild(s),e.appendChild(a),i.appendChild(e);function o(){Vn(e,t.get("show_controls")===!1);let c=Gr(t.get("step")),[l,h]=(t.get("bounds")||[-5,5]).map(Number);for(let x of"abc"){Ta(n[x].name,"color",t.color(x.toUpperCase()));let v=(t.get(x)||["","",""]).map(String);n[x].cells.forEach(({slider:m,box:g},y)=>{_n(m,"min",l),_n(m,"max",h),_n(m,"step",c.value);let w=Qi(v[y]);Number.isFinite(w)&&Number(m.value)!==w&&(m.value=String(w)),_n(m,"aria-valuetext",v[y]),!g.dataset.dirty&&g.value!==v[y]&&(g.value=v[y])})}let[u,d]=t.get("precision_range")||[0,15];if(r.options.length!==d-u+1){r.textContent="";for(let x=u;x<=d;x++)r.appendChild(new Option(String(x),String(x)))}let f=String(t.get("precision")??4);r.value!==f&&(r.value=f)}return{el:e,update:o,reset(){for(let c of"abc")for(let{box:l}of n[c].cells)delete l.dataset.dirty},dispose(){e.remove()}}}function Pv(i,t){if(i.dataset.text===t)return;i.dataset.text=t,i.textContent="";let e=String(t).startsWith("("),n=e?i.appendChild(document.createElement("span")):i;e&&(n.className="tnx-vector");let a=String(t).split(/(?<=,) | (?=[+=−-] )/);a.forEach((s,r)=>{let o=document.createElement("span");o.className="tnx-part",o.textContent=s,n.appendChild(o),r<a.length-1&&n.appendChild(document.createTextNode(" "))})}function em(i){let t=document.createElement("section");t.className="tnx-readout",t.setAttribute("aria-label","Readout");let e=document.createElement("table");e.className="tnx-table";let n=document.createElement("tbody");e.appendChild(n);let a=document.createElement("p");a.className="tnx-status";let s=document.createElement("p");s.className="tnx-summary",s.setAttribute("aria-live","polite"),s.setAttribute("role","status"),t.append(e,a,s),i.appendChild(t);let r=0;function o(c){let l=Array.isArray(c?.readout)?c.readout:[];for(;n.rows.length>l.length;)n.deleteRow(-1);l.forEach((u,d)=>{let f=n.rows[d]||n.insertRow();if(f.cells.length===0){let x=document.createElement("th");x.scope="row",f.append(x,document.createElement("td")),f.cells[1].className="tnx-value"}_n(f,"data-key",u.key),$i(f.cells[0],u.label),Pv(f.cells[1],c.ok===!1?"—":u.value)}),$i(a,(c?.ok===!1?c.error:c?.status)||""),_n(a,"data-state",c?.ok===!1?"error":c?.degenerate?"degenerate":"ok"),clearTimeout(r);let h=c?.ok===!1?c.error||"":c?.summary||c?.status||"";r=setTimeout(()=>{s.textContent!==h&&(s.textContent=h)},350)}return{el:t,update:o,show(c){Vn(t,!c)},dispose(){clearTimeout(r),t.remove()}}}var nm=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),Lv=globalThis[nm]||(globalThis[nm]=(_s(),Pa(ys))),{OrbitControls:im}=Lv;var Ln=new rt(1,.75,.65).normalize(),am=40,sm=28;function Dv(){try{let i=document.createElement("canvas").getContext("webgl2");if(!i)return!1;let t=i.getExtension("WEBGL_debug_renderer_info"),e=t?String(i.getParameter(t.UNMASKED_RENDERER_WEBGL)):"";return i.getExtension("WEBGL_lose_context")?.loseContext(),/swiftshader|llvmpipe|softpipe|software/i.test(e)}catch{return!1}}function bl(i,{onRender:t}){let e=new Wp({antialias:!Dv()});e.setPixelRatio(Math.min(window.devicePixelRatio||1,2));let n=e.domElement;n.className="tnx-canvas",i.appendChild(n);let a=new zp,s=new Bp(am,1,.01,1e3);s.up.set(0,0,1),s.position.copy(Ln).multiplyScalar(6);let r=new im(s,n);r.enableDamping=!1,r.zoomToCursor=!1;let o=0,c=1,l=1,h={target:new rt,distance:6,radius:1,points:[new rt],center:new rt,direction:Ln.clone(),start:Ln.clone()},u=!0;function d(){o=0,t(),e.render(a,s)}function f(){o||(o=requestAnimationFrame(d))}function x(){o&&cancelAnimationFrame(o),d()}function v(){let E=Math.max(1,Math.round(i.clientWidth)),A=Math.max(1,Math.round(i.clientHeight));E===c&&A===l||(c=E,l=A,e.setSize(E,A,!1),s.aspect=E/A,s.updateProjectionMatrix(),u&&M(h.direction),f())}function m(E){let A=E.clone().normalize(),I=new rt().crossVectors(s.up,A);return I.lengthSq()<1e-12&&I.set(1,0,0),I.normalize(),{x:I,y:new rt().crossVectors(A,I),z:A}}function g(E){let{x:A,y:I}=m(E),N=h.points.map(V=>V.clone().sub(h.center).dot(A)),L=h.points.map(V=>V.clone().sub(h.center).dot(I)),P=(Math.min(...N)+Math.max(...N))/2,U=(Math.min(...L)+Math.max(...L))/2;return h.center.clone().addScaledVector(A,P).addScaledVector(I,U)}function y(E){let{x:A,y:I,z:N}=m(E),L=Math.tan(am/2*Math.PI/180),P=L*s.aspect,U=Math.max(.5,1-2*sm/Math.max(c,1)),V=Math.max(.5,1-2*sm/Math.max(l,1)),O=1e-6;for(let Q of h.points){let G=Q.clone().sub(h.target),Z=G.dot(N);O=Math.max(O,Z+Math.abs(G.dot(A))/(P*U),Z+Math.abs(G.dot(I))/(L*V))}return Math.max(O*1.02,h.radius*1.2)}let w=new ResizeObserver(v);w.observe(i),r.addEventListener("change",f),r.addEventListener("start",()=>{u=!1});function p(E,A=!0,I=null){I&&h.start.copy(I),h.points=E.map(P=>P.clone());let N=E[0].clone(),L=E[0].clone();for(let P of E)N.min(P),L.max(P);h.center.copy(N).add(L).multiplyScalar(.5),h.target.copy(h.center),h.radius=Math.max(L.distanceTo(N)/2,.001),A==="keep"?M(s.position.clone().sub(r.target)):A&&M(h.start)}function _(E,A){let I=s.position.clone().sub(r.target),N=I.length(),L=Math.atan2(I.y,I.x)+E,P=Math.PI/2-.01,U=Math.max(-P,Math.min(P,Math.asin(Math.max(-1,Math.min(1,I.z/N)))+A));I.set(Math.cos(U)*Math.cos(L),Math.cos(U)*Math.sin(L),Math.sin(U)).multiplyScalar(N),s.position.copy(r.target).add(I),u=!1,r.update()}function S(E){let A=s.position.clone().sub(r.target).multiplyScalar(E),I=Math.min(Math.max(A.length(),s.near*2),s.far/2);s.position.copy(r.target).addScaledVector(A.normalize(),I),u=!1,r.update()}function b(E,A=.92){return s.updateMatrixWorld(),E.every(I=>{let N=I.clone().project(s);return Math.abs(N.x)<=A&&Math.abs(N.y)<=A&&N.z<1})}function M(E){h.direction.copy(E),u=!0;let A=E.clone().normalize();Math.abs(A.z)>.999&&A.set(0,-.001,Math.sign(A.z)).normalize(),h.target.copy(g(A)),h.distance=y(A),s.near=h.distance/200,s.far=h.distance*50,s.updateProjectionMatrix(),r.target.copy(h.target),s.position.copy(h.target).addScaledVector(A,h.distance),s.lookAt(h.target),r.update(),f()}return{renderer:e,canvas:n,scene:a,camera:s,controls:r,requestRender:f,renderNow:x,resize:v,framePoints:p,inView:b,reset:()=>M(h.start),turn:_,zoom:S,atHome:()=>u,along:E=>M(new rt(E==="x"?1:0,E==="y"?-1:0,E==="z"?1:0)),setBackground:E=>{a.background=new mi(E),f()},size:()=>({width:c,height:l}),dispose(){o&&cancelAnimationFrame(o),w.disconnect(),r.dispose(),e.dispose(),e.forceContextLoss?.(),n.remove()}}}var rm=".tnx-root{--tnx-bg: #fff;--tnx-fg: #1a1a1a;--tnx-muted: #4a4f5c;--tnx-chip: rgba(255,255,255,.92);display:flex;flex-wrap:wrap;gap:12px;align-items:flex-start;font:15px/1.4 system-ui,-apple-system,Segoe UI,Roboto,sans-serif;color:var(--tnx-fg);max-width:100%}.tnx-root.tnx-dark{--tnx-bg: #1b1d24;--tnx-fg: #f2f2f2;--tnx-muted: #c3c7d1;--tnx-chip: rgba(27,29,36,.9)}.tnx-main{flex:1 1 400px;min-width:min(360px,100%);max-width:100%}.tnx-side{flex:1 1 250px;min-width:min(100%,min-content);max-width:100%;container-type:inline-size}.tnx-side.tnx-no-readout{flex-basis:100%}.tnx-toolbar{display:flex;flex-wrap:wrap;gap:4px;margin:0 0 6px;container-type:inline-size}.tnx-toolbar button{font:inherit;font-size:14px;line-height:1.2;padding:5px 7px;min-height:32px;min-width:32px;flex:0 0 auto;white-space:nowrap;border-radius:6px;cursor:pointer;border:1px solid var(--tnx-muted);background:var(--tnx-bg);color:var(--tnx-fg)}.tnx-short{display:none}@container (max-width: 470px){.tnx-toolbar .tnx-long{display:none}.tnx-toolbar .tnx-short{display:inline}.tnx-toolbar button{padding:5px 6px}}.tnx-toolbar button[aria-pressed=true]{background:var(--tnx-fg);color:var(--tnx-bg)}.tnx-toolbar button:focus-visible,.tnx-vertex:focus-visible{outline:3px solid #0072B2;outline-offset:2px}.tnx-stage{position:relative;width:100%;height:var(--tnx-height,clamp(170px, calc(100vh - 310px) ,370px));max-height:80vh;min-height:170px;overflow:hidden;border:1px solid var(--tnx-muted);border-radius:0;background:var(--tnx-bg);touch-action:pan-y;user-select:none;-webkit-user-select:none}.tnx-canvas{display:block;width:100%!important;height:100%!important;outline:none}.tnx-labels{position:absolute;inset:0;pointer-events:none;overflow:hidden}.tnx-label{position:absolute;left:0;top:0;white-space:nowrap;font-weight:700;font-size:19px;line-height:1;will-change:transform}.tnx-arrow,.tnx-axis,.tnx-tick,.tnx-note{padding:2px 4px;border-radius:4px;background:var(--tnx-chip)}.tnx-tick{font-weight:400;font-size:14px;color:var(--tnx-fg)}.tnx-note{font-weight:600;font-size:14px;color:var(--tnx-fg)}.tnx-vertex{pointer-events:auto;cursor:grab;touch-action:pan-y;min-width:34px;min-height:34px;display:flex;align-items:center;justify-content:center;font-size:19px;border-radius:50%;border:3px solid currentColor;background:var(--tnx-chip)}.tnx-dragging .tnx-vertex,.tnx-dragging .tnx-canvas{cursor:grabbing}.tnx-touch-active .tnx-stage,.tnx-touch-active .tnx-vertex{touch-action:none}.tnx-touch-active .tnx-stage{outline:3px solid #0072B2;outline-offset:-3px}.tnx-message,.tnx-error{margin:6px 0 0;padding:4px 10px;border-radius:6px;font-size:15px;border-left:5px solid #e69f00;color:var(--tnx-fg)}.tnx-error,.tnx-message[data-state=error]{border-left-color:#d55e00;font-weight:700}.tnx-tick{z-index:1}.tnx-axis{z-index:2}.tnx-arrow{z-index:3}.tnx-vertex{z-index:5}.tnx-legend{margin:6px 0 0;padding:0 10px;font-size:15px;color:var(--tnx-fg)}.tnx-hint{margin:6px 0 0;font-size:14px;color:var(--tnx-muted)}.tnx-readout{min-width:0;font-size:15px}.tnx-root .tnx-readout table{border-collapse:collapse;width:100%}.tnx-root .tnx-readout th{text-align:left;line-height:1.25;padding:1px 10px 1px 0;white-space:nowrap;font-weight:700;vertical-align:top}.tnx-root .tnx-readout td{padding:1px 0;font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;line-height:1.25}.tnx-root .tnx-vector,.tnx-root .tnx-part{white-space:nowrap}@container (max-width: 340px){.tnx-readout tr,.tnx-readout th,.tnx-root .tnx-readout td{display:block}.tnx-root .tnx-readout .tnx-vector{white-space:normal}.tnx-root .tnx-readout td{padding:0 0 4px .8em}}.tnx-status{margin:6px 0 0;padding:4px 8px;border-left:4px solid #009e73}.tnx-status[data-state=degenerate]{border-left-color:#e69f00}.tnx-status[data-state=error]{border-left-color:#d55e00;font-weight:700}.tnx-summary{position:absolute;width:1px;height:1px;margin:-1px;overflow:hidden;clip:rect(0 0 0 0);white-space:nowrap}.tnx-nogl{padding:12px;border:1px solid var(--tnx-muted);border-radius:6px}.tnx-controls{flex:1 1 100%;display:flex;flex-direction:column;gap:4px;font-size:15px}.tnx-vertex-row{display:flex;align-items:baseline;gap:4px 12px}.tnx-vertex-name{flex:none;font-weight:700;font-size:16px;width:1.2em}.tnx-coords{display:flex;flex-wrap:wrap;align-items:center;gap:4px 12px;min-width:0}.tnx-coord{display:inline-flex;align-items:center;gap:4px}.tnx-axis-name{display:inline-block;width:.8em;color:var(--tnx-muted)}.tnx-slider{width:7em;margin:0;accent-color:#0072B2}.tnx-exact,.tnx-decimals select{font:inherit;font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;width:4.6em;padding:2px 4px;border:1px solid var(--tnx-muted);border-radius:4px;background:var(--tnx-bg);color:var(--tnx-fg)}.tnx-decimals select{width:auto}.tnx-exact:focus-visible,.tnx-slider:focus-visible,.tnx-decimals select:focus-visible{outline:3px solid #0072B2;outline-offset:1px}";var om="trinormal-explorer-style";function cm(i=document){if(i.getElementById(om))return;let t=i.createElement("style");t.id=om,t.textContent=rm,i.head.appendChild(t)}var lm={A:{light:"#333333",dark:"#E6E6E6"}};function Ss(i=document){let t=i.body;return t?t.dataset.jpThemeLight!==void 0?t.dataset.jpThemeLight==="false":t.dataset.mdColorScheme!==void 0?t.dataset.mdColorScheme==="slate":i.documentElement.dataset.mdColorScheme==="slate":!1}function xl(i,t=document){let e=Ss(t),n=new MutationObserver(()=>{let s=Ss(t);s!==e&&(e=s,i(e))}),a=["data-md-color-scheme","data-jp-theme-light","data-jp-theme-name"];return t.body&&n.observe(t.body,{attributes:!0,attributeFilter:a}),n.observe(t.documentElement,{attributes:!0,attributeFilter:a}),()=>n.disconnect()}function $n(i,t,e){let n=i&&i[t]||lm[t]||lm.A;return e?n.dark:n.light}function ta(i){return i?{background:"#1b1d24",text:"#f2f2f2",grid:"#4a4f5c",gridMajor:"#6b7180",line:"#ffd166"}:{background:"#ffffff",text:"#1a1a1a",grid:"#d4d7de",gridMajor:"#9aa0ab",line:"#b3261e"}}var Ov=10,Fv=600;function yl({root:i,stageEl:t,controls:e,canvas:n,activeClass:a}){let s=!1;function r(d){s=d,i.classList.toggle(a,d),e.touches.ONE=d?Hp.ROTATE:null,n.style.touchAction=d?"none":"pan-y"}r(!1);let o=null,c=d=>{o=d.pointerType==="touch"?{x:d.clientX,y:d.clientY,t:performance.now(),id:d.pointerId}:null},l=d=>{if(!o||d.pointerId!==o.id)return;let f=Math.hypot(d.clientX-o.x,d.clientY-o.y)<Ov&&performance.now()-o.t<Fv;o=null,f&&!s&&r(!0)},h=d=>{s&&!i.contains(d.target)&&r(!1)},u=i.ownerDocument||document;return t.addEventListener("pointerdown",c,{capture:!0}),t.addEventListener("pointerup",l),u.addEventListener("pointerdown",h,{capture:!0}),{active:()=>s,dispose(){t.removeEventListener("pointerdown",c,{capture:!0}),t.removeEventListener("pointerup",l),u.removeEventListener("pointerdown",h,{capture:!0})}}}var _l=["a","b","c","winding","precision","step","bounds","show_parallelogram","show_unit_normal","show_readout","show_controls","precision_range","palette","state","message"],pm={a:["ax","ay","az"],b:["bx","by","bz"],c:["cx","cy","cz"]},mm=new Set(Object.values(pm).flat()),Bv=new Set([...mm,"winding","precision","show_parallelogram","show_unit_normal"]),hm=.7,dm=.5;function kv(i,t){return!(i>0)||!(t>0)||!Number.isFinite(i)?1:2**Math.round(Math.log2(t/i))}function vl(i,t){let e=kv(i,t);return{factor:e,length:i*e}}var zv="⁰¹²³⁴⁵⁶⁷⁸⁹";function Vv(i){let t=Math.round(Math.log2(i));return Math.abs(t)<=12?String(2**Math.abs(t)):"2"+[...String(Math.abs(t))].map(e=>zv[Number(e)]).join("")}function um(i,t=!1){if(i===1)return t?"N/|N|":"N";let e=Vv(i);return i<1?t?`N/(${e}|N|)`:`N/${e}`:t?`${e}N/|N|`:`${e}N`}var Hv={A:225*Math.PI/180,B:-30*Math.PI/180,C:90*Math.PI/180},fm={ABC:"A→B→C",ACB:"A→C→B"};function Gv(i){if(!(i.length()>0))return Ln.clone();let t=i.clone().normalize(),e=Ln.dot(t);if(e>=.35&&e<=.8)return Ln.clone();let n=Ln.clone(),a=Math.abs(Ln.dot(t)-.65);for(let s of[20,35,55])for(let r=0;r<8;r++){let o=(r*45+37)*Math.PI/180,c=s*Math.PI/180,l=new rt(Math.cos(c)*Math.cos(o),Math.cos(c)*Math.sin(o),Math.sin(c)),h=Math.abs(l.dot(t)-.65);h<a-1e-9&&([n,a]=[l,h])}return n}function vn(i,t,e){let n=document.createElement(i);return t&&(n.className=t),e!==void 0&&(n.textContent=e),n}function ws(i,t,e){let n=vn("button","tnx-button",i);return n.type="button",t&&(n.setAttribute("aria-label",t),n.title=t),n.addEventListener("click",e),n}var Wv=0;function jv({model:i,el:t}){cm(t.ownerDocument||document);let e=`v${++Wv}-${Math.random().toString(36).slice(2,8)}`,n=vn("div","tnx-root");n.dataset.lmSuppressShortcuts="true";let a=vn("div","tnx-main"),s=vn("div","tnx-side"),r=vn("div","tnx-toolbar");r.setAttribute("role","toolbar"),r.setAttribute("aria-label","3D view");let o=vn("div","tnx-stage"),c=vn("p","tnx-message");c.hidden=!0,c.setAttribute("role","status");let l=vn("p","tnx-legend");l.hidden=!0;let h=vn("p","tnx-error");h.hidden=!0,h.setAttribute("role","alert");let u=vn("p","tnx-hint","Drag empty space to turn the view, scroll or pinch to zoom; x, y, z look along an axis. Drag A, B or C to move a point, or Tab to it and press the arrow keys (x, y) or Page Up/Page Down (z). On a touch screen, tap the view first, then drag.");a.append(r,o,c,h,l),n.append(a,s),t.appendChild(n);let d=em(s);s.appendChild(u);let f=0,x={};function v(nt){let St=pm[nt];if(!St||!St.some(Qt=>Qt in x))return nt in x?x[nt].value:i.get(nt);let wt=i.get(nt)||["","",""];return St.map((Qt,Ht)=>Qt in x?x[Qt].value:wt[Ht])}function m(nt){f+=1;for(let[St,wt]of Object.entries(nt)){let Qt=!mm.has(St)||Number.isFinite(Qi(wt));Bv.has(St)&&Qt&&(x[St]={value:wt,seq:f})}i.send({edit:nt,seq:f,view:e,base:i.get("version")??0})}let g=Ss(),y=nt=>{let St=ta(g);switch(nt){case"edge":case"paraEdge":case"ring":case"unit":return St.text;case"para":return $n(v("palette"),"N",g);case"line":return St.line;default:return $n(v("palette"),nt,g)}},w=tm(n,{get:v,edit:m,color:nt=>y(nt)}),p;try{p=bl(o,{onRender:()=>_.layout(p.camera,p.size())})}catch{o.remove(),u.remove(),a.appendChild(vn("p","tnx-nogl","This browser cannot draw the 3D view (WebGL is not available). The readout still follows the values."));let St=()=>{d.show(!0),d.update(i.get("state")),w.update()};St();for(let wt of _l)i.on("change:"+wt,St);return()=>{for(let wt of _l)i.off("change:"+wt,St);n.remove()}}let _=new gl(o),S=new ml(p.scene),b=ws("",null,()=>m({winding:v("winding")==="ACB"?"ABC":"ACB"})),M=(nt,St)=>ws(St,null,()=>m({[nt]:!v(nt)})),E=M("show_parallelogram","");E.append(vn("span","tnx-long","Parallelogram"),vn("span","tnx-short","▱")),E.setAttribute("aria-label","Parallelogram");let A=M("show_unit_normal","N/|N|");A.setAttribute("aria-label","Unit normal N/|N|"),A.title="Show the unit normal N/|N|",E.title="Show the parallelogram on U and V (area |N|)";let I=ws("","Reset view",()=>{L&&ht(et(U||Z(),v("winding")),!0),p.reset()});I.append(vn("span","tnx-long","Reset view"),vn("span","tnx-short","Reset")),I.title="Reset view: frame the triangle and its arrows again",r.append(I,ws("x","View along the x axis",()=>p.along("x")),ws("y","View along the y axis",()=>p.along("y")),ws("z","View along the z axis",()=>p.along("z")),b,E,A);let N={};for(let nt of"ABC"){let wt=_.label("v:"+nt,"vertex",nt).el;wt.dataset.vertex=nt,wt.tabIndex=0,wt.dataset.lmSuppressShortcuts="true",wt.setAttribute("role","button"),wt.setAttribute("aria-roledescription","movable point"),wt.setAttribute("aria-keyshortcuts","ArrowLeft ArrowRight ArrowUp ArrowDown PageUp PageDown"),N[nt]=wt}for(let[nt,St]of[["U","U"],["V","V"],["N","N"],["unit","N/|N|"]])_.label("arrow:"+nt,"arrow",St);for(let nt of"xyz")_.label("axis:"+nt,"axis",nt);let L=null,P=!1,U=null,V=!1,O=null,Q={},G={};function Z(){let nt=[v("a"),v("b"),v("c")].map(jp);if(nt.every(Boolean))return nt;let St=v("state");if(St&&St.ok&&St.points){let wt=["A","B","C"].map(Qt=>St.points[Qt]);if(wt.every(Qt=>Array.isArray(Qt)&&Qt.every(Number.isFinite)))return wt}return U}function et(nt,St){let wt=Math.max(...nt.flat().map(Math.abs)),Qt=[[0,1],[0,2],[1,2]].map(([J,ft])=>Math.hypot(...nt[J].map((R,k)=>R-nt[ft][k]))),Ht=Math.max(...Qt),be=Ht===0?!0:wt<=6*Ht,ne=Xp(be?wt||Ht||1:Ht),B=be?new rt:new rt(...[0,1,2].map(J=>Number(((nt[0][J]+nt[1][J]+nt[2][J])/3).toPrecision(3)))),Ee=nt.map(J=>new rt(J[0]-B.x,J[1]-B.y,J[2]-B.z).divideScalar(ne)),$t=Math.max(...Ee.map(J=>Math.max(Math.abs(J.x),Math.abs(J.y),Math.abs(J.z)))),Jt=qp(Math.max($t,1e-9)/1.5),dt=Jt*(Math.floor($t/Jt+1e-9)+1.5),se=Ee.slice(),[At,Lt,D]=Ee,T=new rt().crossVectors(Lt.clone().sub(At),D.clone().sub(At));St==="ACB"&&T.negate();let W=Math.max(At.distanceTo(Lt),At.distanceTo(D),Lt.distanceTo(D)),at=At.clone().add(Lt).add(D).divideScalar(3);T.length()>0&&(se.push(at.clone().add(T.clone().setLength(vl(T.length()*ne,hm*W).length))),v("show_unit_normal")&&se.push(at.clone().add(T.clone().setLength(vl(1/ne,dm*W).length))));let tt=se[0].clone(),lt=se[0].clone();for(let J of se)tt.min(J),lt.max(J);let ut=tt.clone().add(lt).multiplyScalar(.5),$=Math.max(lt.distanceTo(tt)/2,.001);return{S:ne,offset:B,includeOrigin:be,radius:$,center:ut,box:se,L:dt,t:Jt,start:Gv(T)}}function ht(nt,St){L=nt,St!==!1&&p.framePoints(nt.box,St,nt.start);let wt=L.radius*.014,Qt=S.setAxes(nt.L,nt.t,wt*.5,y,nt.includeOrigin);S.setGrid(nt.L,nt.t,ta(g),nt.includeOrigin),_.hide("tick:"),Qt.forEach((Ht,be)=>{let fe=`tick:${Ht.axis}:${be}`;_.label(fe,"tick",Yp(Ht.value*nt.S)),_.place(fe,Ht.position,{offset:16,angle:Ht.axis==="z"?0:-Math.PI/2})});for(let Ht of"xyz"){let be=new rt(Ht==="x"?nt.L:0,Ht==="y"?nt.L:0,Ht==="z"?nt.L:0);_.place("axis:"+Ht,be,{away:new rt,offset:18,visible:nt.includeOrigin}),Ta(_.items.get("axis:"+Ht).el,"color",y(Ht))}}function Pt(nt,St){return nt&&St&&nt.S===St.S&&nt.includeOrigin===St.includeOrigin&&nt.offset.equals(St.offset)}function Y(nt){let St=v("state"),wt=St&&St.ok!==!1&&Array.isArray(St.readout)?St.readout.find(Qt=>Qt.key===nt):null;return wt?wt.value:null}function ct(){let nt=Z(),St=v("state")||{},wt=v("winding")==="ACB"?"ACB":"ABC";$i(b,`⇄ ${fm[wt]}`),_n(b,"aria-label",`Flip the order of the vertices, now ${fm[wt]}`),_n(b,"title",b.getAttribute("aria-label")),_n(E,"aria-pressed",!!v("show_parallelogram")),_n(A,"aria-pressed",!!v("show_unit_normal")),d.show(!!v("show_readout")),s.classList.toggle("tnx-no-readout",!v("show_readout")),v("show_readout")&&d.update(St);let Qt=St.ok===!1?St.error||St.status:St.degenerate?St.status:"";Vn(c,!Qt),$i(c,Qt||""),_n(c,"data-state",St.ok===!1?"error":"degenerate");let Ht=i.get("message")||"";Vn(h,!Ht),$i(h,Ht),w.update();for(let j of"ABC"){let it=v(j.toLowerCase())||[];_n(N[j],"aria-label",`Point ${j} at (${it.join(", ")}). Arrow keys move x and y, Page Up and Page Down move z.`)}if(!nt){S.root.visible=!1,p.requestRender();return}if(S.root.visible=!0,U=nt,!P){let j=et(nt,wt);if(!L)ht(j,!0);else if(V)ht(j,p.atHome()?!0:"keep");else if(!Pt(L,j))ht(j,"keep");else{(j.L!==L.L||j.t!==L.t)&&ht({...j,center:L.center,radius:L.radius},!1);let it=nt.map(st=>new rt(st[0]-L.offset.x,st[1]-L.offset.y,st[2]-L.offset.z).divideScalar(L.S));p.inView(it)||ht(j,"keep")}}V=!1;let{S:be,offset:fe}=L,[ne,B,Ee]=nt.map(j=>new rt(j[0]-fe.x,j[1]-fe.y,j[2]-fe.z).divideScalar(be)),[$t,Jt]=wt==="ABC"?[B,Ee]:[Ee,B],dt=ne.clone().add(B).add(Ee).divideScalar(3),se=$t.clone().sub(ne),At=Jt.clone().sub(ne),Lt=new rt().crossVectors(se,At),D=Lt.length(),T=!!St.degenerate||!(D>0)||!Number.isFinite(D),W=Math.max(se.length(),At.length(),$t.distanceTo(Jt),1e-9),at=new rt,tt=1;if(!T){let j=vl(D*be,hm*W);tt=j.factor,at=Lt.clone().setLength(j.length)}let lt=null,ut=1;if(!T&&v("show_unit_normal")){let j=vl(1/be,dm*W);ut=j.factor,lt=Lt.clone().setLength(j.length)}_.label("arrow:N","arrow",um(tt)),_.label("arrow:unit","arrow",um(ut,!0)),G={N:tt,unit:lt?ut:null};let $=L.radius*.014,J={A:ne,B,C:Ee,P:$t,Q:Jt,centroid:dt,nDraw:at,unitDraw:lt,degenerate:T,showParallelogram:!!v("show_parallelogram"),r:$};S.update(J),O={A:ne,B,C:Ee},Q={U:$t,V:Jt,N:T?null:dt.clone().add(at),unit:lt?dt.clone().add(lt):null};for(let j of"ABC")_.place("v:"+j,J[j],{away:dt,offset:30,angle:Hv[j]}),Ta(N[j],"color",y(j));_.place("arrow:U",ne.clone().lerp($t,.5),{away:dt,offset:20,visible:se.length()>0}),_.place("arrow:V",ne.clone().lerp(Jt,.5),{away:dt,offset:20,visible:At.length()>0});let ft=dt.clone().add(at);_.place("arrow:N",ft,{away:dt,offset:20,angle:0,visible:!T}),_.place("arrow:unit",lt?dt.clone().add(lt):null,{away:dt,offset:20,angle:Math.PI,visible:!!lt});for(let[j,it]of[["U","U"],["V","V"],["N","N"],["unit","unit"]])Ta(_.items.get("arrow:"+j).el,"color",y(it));let R=Y("magnitude"),k=Y("area"),H=J.showParallelogram&&!T&&R!==null&&k!==null;Vn(l,!H),H&&$i(l,`Parallelogram on U and V: area |N| = ${R}. Triangle: area |N|/2 = ${k}.`),p.requestRender()}function mt(){if(n.classList.toggle("tnx-dark",g),p.setBackground(ta(g).background),S.paint(y),L){S.setGrid(L.L,L.t,ta(g),L.includeOrigin);for(let nt of"xyz")Ta(_.items.get("axis:"+nt).el,"color",y(nt))}ct()}let Tt=yl({root:n,stageEl:o,controls:p.controls,canvas:p.canvas,activeClass:"tnx-touch-active"}),gt=Zp({touchActive:Tt.active,container:o,canvas:p.canvas,camera:p.camera,scale:()=>L?.S??1,grid:()=>Gr(v("step")),bounds:()=>v("bounds"),values:nt=>(v(nt.toLowerCase())||["","",""]).map(String),position:nt=>O?O[nt]:null,write(nt){m(nt),Dt()},dragging(nt){P=nt,nt||ct()}}),Ot=!1,ge=()=>{Ot||(Ot=!0,queueMicrotask(()=>{Ot&&(Ot=!1,ct())}))},Dt=()=>{Ot=!1,ct(),p.renderNow()},kt=()=>mt(),Yt={};for(let nt of _l)Yt[nt]=nt==="palette"?kt:ge,i.on("change:"+nt,Yt[nt]);Yt.last_edit=()=>{let nt=i.get("last_edit")||{};if(nt.view===e){for(let[St,wt]of Object.entries(x))wt.seq<=nt.seq&&delete x[St];ge()}},Yt.version=()=>{gt.cancel(),x={},w.reset(),V=!0,ge()},i.on("change:last_edit",Yt.last_edit),i.on("change:version",Yt.version);let Xt=xl(nt=>{g=nt,mt()}),Ae=nt=>nt.A.clone().add(nt.B).add(nt.C).divideScalar(3);return n.tnxProject=()=>{if(!O||!L)return null;let{width:nt,height:St}=p.size();p.camera.updateMatrixWorld();let wt={};for(let[fe,ne]of Object.entries({...O,...Q})){if(!ne)continue;let B=ne.clone().project(p.camera);wt[fe]=[(B.x+1)/2*nt,(1-B.y)/2*St]}let Qt=p.camera.position.distanceTo(p.controls.target),Ht=fe=>fe&&O?fe.clone().sub(Ae(O)).multiplyScalar(L.S).toArray():null,be={N:Ht(Q.N),unit:Ht(Q.unit),scales:{...G}};return{width:nt,height:St,distance:Qt,points:wt,drawn:be,values:["a","b","c"].map(fe=>(v(fe)||[]).map(String))}},p.resize(),mt(),()=>{for(let nt of _l)i.off("change:"+nt,Yt[nt]);i.off("change:last_edit",Yt.last_edit),i.off("change:version",Yt.version),Tt.dispose(),Xt(),gt(),_.dispose(),S.dispose(),p.dispose(),d.dispose(),w.dispose(),n.remove()}}var Dd={render:jv};var gm=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),Xv=globalThis[gm]||(globalThis[gm]=(_s(),Pa(ys))),{LineMaterial:qr}=Xv;var bm=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),qv=globalThis[bm]||(globalThis[bm]=(_s(),Pa(ys))),{LineSegments2:Ud}=qv;var xm=Symbol.for("trinormal.three@0.187.0#84c0f911a589"),Yv=globalThis[xm]||(globalThis[xm]=(_s(),Pa(ys))),{LineSegmentsGeometry:Od}=Yv;var As=Math.pow(2,-24),Yr=Symbol("SKIP_GENERATION"),Ml={strategy:0,maxDepth:40,targetLeafSize:10,useSharedArrayBuffer:!1,setBoundingBox:!0,onProgress:null,indirect:!1,verbose:!0,range:null,[Yr]:!1};function ve(i,t,e){return e.min.x=t[i],e.min.y=t[i+1],e.min.z=t[i+2],e.max.x=t[i+3],e.max.y=t[i+4],e.max.z=t[i+5],e}function Jr(i){let t=-1,e=-1/0;for(let n=0;n<3;n++){let a=i[n+3]-i[n];a>e&&(e=a,t=n)}return t}function Fd(i,t,e){for(let n=0;n<3;n++){let a=t[i+2*n],s=t[i+2*n+1],r=a-s,o=a+s;r<e[n]&&(e[n]=r),o>e[n+3]&&(e[n+3]=o)}}function Sl(i){let t=i[3]-i[0],e=i[4]-i[1],n=i[5]-i[2];return 2*(t*e+e*n+n*t)}function ie(i,t){return t[i+15]===65535}function me(i,t){return t[i+6]}function ye(i,t){return t[i+14]}function de(i){return i+8}function ue(i,t){let e=t[i+6];return i+e*8}function Es(i,t){return t[i+7]}function wl(i,t,e,n,a){let s=1/0,r=1/0,o=1/0,c=-1/0,l=-1/0,h=-1/0,u=1/0,d=1/0,f=1/0,x=-1/0,v=-1/0,m=-1/0,g=i.offset||0;for(let y=(t-g)*6,w=(t+e-g)*6;y<w;y+=6){let p=i[y+0],_=i[y+1],S=p-_,b=p+_;S<s&&(s=S),b>c&&(c=b),p<u&&(u=p),p>x&&(x=p);let M=i[y+2],E=i[y+3],A=M-E,I=M+E;A<r&&(r=A),I>l&&(l=I),M<d&&(d=M),M>v&&(v=M);let N=i[y+4],L=i[y+5],P=N-L,U=N+L;P<o&&(o=P),U>h&&(h=U),N<f&&(f=N),N>m&&(m=N)}n[0]=s,n[1]=r,n[2]=o,n[3]=c,n[4]=l,n[5]=h,a[0]=u,a[1]=d,a[2]=f,a[3]=x,a[4]=v,a[5]=m}var bi=8,kd=8,Bd=new Int32Array(bi),gi=new Float32Array(bi*6),Ts=new Float32Array(bi*6),ti=new Float32Array(6),Al=new Float32Array(6),ea=new Int32Array(kd),_m=new Float32Array(kd*6);function Zv(i,t,e,n){for(let a=0;a<3;a++){let s=t[i+2*a],r=t[i+2*a+1],o=s-r,c=s+r;o<e[n+a]&&(e[n+a]=o),c>e[n+a+3]&&(e[n+a+3]=c)}}function vm(i,t){let e=i[t+3]-i[t],n=i[t+4]-i[t+1],a=i[t+5]-i[t+2];return 2*(e*n+n*a+a*e)}function Mm(i,t,e,n,a,s){let r=-1,o=0;if(s===0)r=Jr(t),r!==-1&&(o=(t[r]+t[r+3])/2);else if(s===1)r=Jr(i),r!==-1&&(o=Qv(e,n,a,r));else if(s===2){let c=Sl(i),l=1.25*a,h=e.offset||0,u=(n-h)*6,d=(n+a-h)*6;for(let f=0;f<3;f++){let x=t[f],g=(t[f+3]-x)/bi;if(a<kd){for(let y=0;y<a;y++){let w=u+y*6,p=e[w+2*f],_=y;for(;_>0&&e[ea[_-1]+2*f]>p;)ea[_]=ea[_-1],_--;ea[_]=w}for(let y=0;y<3;y++)ti[y]=1/0,ti[y+3]=-1/0,Al[y]=1/0,Al[y+3]=-1/0;for(let y=a-1;y>=0;y--)Fd(ea[y],e,Al),_m.set(Al,y*6);for(let y=0;y<a-1;y++){Fd(ea[y],e,ti);let w=e[ea[y+1]+2*f];if(e[ea[y]+2*f]===w)continue;let p=y+1,_=a-p,S=Sl(ti)/c,b=vm(_m,p*6)/c,M=1+1.25*(S*p+b*_);M<l&&(r=f,l=M,o=w)}}else{for(let p=0;p<bi;p++){Bd[p]=0;for(let _=0;_<3;_++)gi[p*6+_]=1/0,gi[p*6+_+3]=-1/0}for(let p=u;p<d;p+=6){let b=~~((e[p+2*f]-x)/g);b>=bi&&(b=bi-1),Bd[b]++,Zv(p,e,gi,b*6)}let y=(bi-1)*6;for(let p=0;p<6;p++)Ts[y+p]=gi[y+p];for(let p=bi-2;p>=0;p--){let _=p*6,S=_+6;for(let b=0;b<3;b++)Ts[_+b]=Math.min(gi[_+b],Ts[S+b]),Ts[_+b+3]=Math.max(gi[_+b+3],Ts[S+b+3])}let w=0;for(let p=0;p<bi-1;p++){let _=p*6,S=Bd[p];if(S!==0)for(let I=0;I<3;I++)w===0?(ti[I]=gi[_+I],ti[I+3]=gi[_+I+3]):(ti[I]=Math.min(ti[I],gi[_+I]),ti[I+3]=Math.max(ti[I+3],gi[_+I+3]));w+=S;let b=0,M=0;w!==0&&(b=Sl(ti)/c);let E=a-w;E!==0&&(M=vm(Ts,_+6)/c);let A=1+1.25*(b*w+M*E);A<l&&(r=f,l=A,o=x+g+p*g)}}}}else console.warn(`BVH: Invalid build strategy value ${s} used.`);return{axis:r,pos:o}}function Qv(i,t,e,n){let a=0,s=i.offset;for(let r=t,o=t+e;r<o;r++)a+=i[(r-s)*6+n*2];return a/e}function Sm(i,t,e,n,a,s){let r=n,o=n+a-1,c=s.pos,l=s.axis*2,h=e.offset||0;for(;;){for(;r<=o&&e[(r-h)*6+l]<c;)r++;for(;r<=o&&e[(o-h)*6+l]>=c;)o--;if(r<o){for(let u=0;u<t;u++){let d=i[r*t+u];i[r*t+u]=i[o*t+u],i[o*t+u]=d}for(let u=0;u<6;u++){let d=r-h,f=o-h,x=e[d*6+u];e[d*6+u]=e[f*6+u],e[f*6+u]=x}r++,o--}else return r}}var $v=Math.pow(2,32),Is=new Float32Array(6),El=new Float32Array(6);function tM(i,t,e,n,a,s){let{maxDepth:r,verbose:o,targetLeafSize:c,_strictLeafSize:l=1/0,strategy:h,onProgress:u,useSharedArrayBuffer:d=!1}=a,f=i.primitiveBuffer,x=i.primitiveBufferStride,v=d?SharedArrayBuffer:ArrayBuffer,m=new v(32*Math.max(1,2*Math.ceil(n)-1)),g=new Float32Array(m),y=new Uint32Array(m),w=new Uint16Array(m),p=0,_=!1;return wl(t,e,n,Is,El),M(e,n,0),m.slice(0,p*32);function S(E){u&&u((E-s.offset)/s.count)}function b(E,A,I){let N=E*2;y[E+6]=A,w[N+14]=I,w[N+15]=65535,S(A+I)}function M(E,A,I){let N=p++,L=N*8;g.set(Is,L),!_&&I>=r&&(_=!0,o&&console.warn(`BVH: Max depth of ${r} reached when generating BVH. Consider increasing maxDepth.`));let P=A>l;if(A<=c&&!P||I>=r){b(L,E,A);return}let U=Mm(Is,El,t,E,A,h),V=U.axis===-1?-1:Sm(f,x,t,E,A,U);if(U.axis===-1||V===E||V===E+A){if(!P){b(L,E,A);return}U.axis=Math.max(0,Jr(Is)),V=E+Math.max(1,Math.floor(A/2))}y[L+7]=U.axis;let O=V-E;wl(t,E,O,Is,El),M(E,O,I+1);let Q=p-N;if(Q>$v)throw new Error("MeshBVH: Cannot store relative child node offset greater than 32 bits.");y[L+6]=Q;let G=A-O;wl(t,V,G,Is,El),M(V,G,I+1)}}function wm(i,t){let e=i.getRootRanges(t.range),n=e[0],a=e[e.length-1],s={offset:n.offset,count:a.offset+a.count-n.offset},r=new Float32Array(6*s.count);r.offset=s.offset,i.computePrimitiveBounds(s.offset,s.count,r),i._roots=e.map(o=>tM(i,r,o.offset,o.count,t,s))}var na=class{constructor(t){this._getNewPrimitive=t,this._primitives=[]}getPrimitive(){let t=this._primitives;return t.length===0?this._getNewPrimitive():t.pop()}releasePrimitive(t){this._primitives.push(t)}};var zd=class{constructor(){this.float32Array=null,this.uint16Array=null,this.uint32Array=null;let t=[],e=null;this.setBuffer=n=>{e&&t.push(e),e=n,this.float32Array=new Float32Array(n),this.uint16Array=new Uint16Array(n),this.uint32Array=new Uint32Array(n)},this.clearBuffer=()=>{e=null,this.float32Array=null,this.uint16Array=null,this.uint32Array=null,t.length!==0&&this.setBuffer(t.pop())}}},Zt=new zd;var ia,Cs,Rs=[],Tl=new na(()=>new rn);function Am(i,t,e,n,a,s){ia=Tl.getPrimitive(),Cs=Tl.getPrimitive(),Rs.push(ia,Cs),Zt.setBuffer(i._roots[t]);let r=Vd(0,i.geometry,e,n,a,s);Zt.clearBuffer(),Tl.releasePrimitive(ia),Tl.releasePrimitive(Cs),Rs.pop(),Rs.pop();let o=Rs.length;return o>0&&(Cs=Rs[o-1],ia=Rs[o-2]),r}function Vd(i,t,e,n,a=null,s=0,r=0){let{float32Array:o,uint16Array:c,uint32Array:l}=Zt,h=i*2;if(ie(h,c)){let d=me(i,l),f=ye(h,c);return ve(i,o,ia),n(d,f,!1,r,s+i/8,ia)}else{let A=function(N){let{uint16Array:L,uint32Array:P}=Zt,U=N*2;for(;!ie(U,L);)N=de(N),U=N*2;return me(N,P)},I=function(N){let{uint16Array:L,uint32Array:P}=Zt,U=N*2;for(;!ie(U,L);)N=ue(N,P),U=N*2;return me(N,P)+ye(U,L)},d=de(i),f=ue(i,l),x=d,v=f,m,g,y,w;if(a&&(y=ia,w=Cs,ve(x,o,y),ve(v,o,w),m=a(y),g=a(w),g<m)){x=f,v=d;let N=m;m=g,g=N,y=w}y||(y=ia,ve(x,o,y));let p=ie(x*2,c),_=e(y,p,m,r+1,s+x/8),S;if(_===2){let N=A(x),P=I(x)-N;S=n(N,P,!0,r+1,s+x/8,y)}else S=_&&Vd(x,t,e,n,a,s,r+1);if(S)return!0;w=Cs,ve(v,o,w);let b=ie(v*2,c),M=e(w,b,g,r+1,s+v/8),E;if(M===2){let N=A(v),P=I(v)-N;E=n(N,P,!0,r+1,s+v/8,w)}else E=M&&Vd(v,t,e,n,a,s,r+1);return!!E}}var Kr=new Zt.constructor,Il=new Zt.constructor,aa=new na(()=>new rn),Ns=new rn,Ps=new rn,Gd=new rn,Wd=new rn,jd=!1;function Em(i,t,e,n){if(jd)throw new Error("MeshBVH: Recursive calls to bvhcast not supported.");jd=!0;let a=i._roots,s=t._roots,r,o=0,c=0,l=new Je().copy(e).invert();for(let h=0,u=a.length;h<u;h++){Kr.setBuffer(a[h]),c=0;let d=aa.getPrimitive();ve(0,Kr.float32Array,d),d.applyMatrix4(l);for(let f=0,x=s.length;f<x&&(Il.setBuffer(s[f]),r=ei(0,0,e,l,n,o,c,0,0,d),Il.clearBuffer(),c+=s[f].byteLength/32,!r);f++);if(aa.releasePrimitive(d),Kr.clearBuffer(),o+=a[h].byteLength/32,r)break}return jd=!1,r}function ei(i,t,e,n,a,s=0,r=0,o=0,c=0,l=null,h=!1){let u,d;h?(u=Il,d=Kr):(u=Kr,d=Il);let f=u.float32Array,x=u.uint32Array,v=u.uint16Array,m=d.float32Array,g=d.uint32Array,y=d.uint16Array,w=i*2,p=t*2,_=ie(w,v),S=ie(p,y),b=!1;if(S&&_)h?b=a(me(t,g),ye(t*2,y),me(i,x),ye(i*2,v),c,r+t/8,o,s+i/8):b=a(me(i,x),ye(i*2,v),me(t,g),ye(t*2,y),o,s+i/8,c,r+t/8);else if(S){let M=aa.getPrimitive();ve(t,m,M),M.applyMatrix4(e);let E=de(i),A=ue(i,x);ve(E,f,Ns),ve(A,f,Ps);let I=M.intersectsBox(Ns),N=M.intersectsBox(Ps);b=I&&ei(t,E,n,e,a,r,s,c,o+1,M,!h)||N&&ei(t,A,n,e,a,r,s,c,o+1,M,!h),aa.releasePrimitive(M)}else{let M=de(t),E=ue(t,g);ve(M,m,Gd),ve(E,m,Wd);let A=l.intersectsBox(Gd),I=l.intersectsBox(Wd);if(A&&I)b=ei(i,M,e,n,a,s,r,o,c+1,l,h)||ei(i,E,e,n,a,s,r,o,c+1,l,h);else if(A)if(_)b=ei(i,M,e,n,a,s,r,o,c+1,l,h);else{let N=aa.getPrimitive();N.copy(Gd).applyMatrix4(e);let L=de(i),P=ue(i,x);ve(L,f,Ns),ve(P,f,Ps);let U=N.intersectsBox(Ns),V=N.intersectsBox(Ps);b=U&&ei(M,L,n,e,a,r,s,c,o+1,N,!h)||V&&ei(M,P,n,e,a,r,s,c,o+1,N,!h),aa.releasePrimitive(N)}else if(I)if(_)b=ei(i,E,e,n,a,s,r,o,c+1,l,h);else{let N=aa.getPrimitive();N.copy(Wd).applyMatrix4(e);let L=de(i),P=ue(i,x);ve(L,f,Ns),ve(P,f,Ps);let U=N.intersectsBox(Ns),V=N.intersectsBox(Ps);b=U&&ei(E,L,n,e,a,r,s,c,o+1,N,!h)||V&&ei(E,P,n,e,a,r,s,c,o+1,N,!h),aa.releasePrimitive(N)}}return b}var Rl=new class{constructor(){let i=null,t=null,e=null,n=!1;this.root=null,this.buffer=null,this.uint32Array=null,this.uint16Array=null,this.setBVH=(s,r)=>{if(n)throw new Error("BVHTraversalHelper: cannot call setBVH during an active traversal.");this.root=r,this.buffer=i=s._roots[r],this.uint16Array=e=new Uint16Array(i),this.uint32Array=t=new Uint32Array(i)},this.reset=()=>{this.root=null,this.buffer=i=null,this.uint16Array=e=null,this.uint32Array=t=null},this.getRangeStart=s=>{let r=s*2;for(;!ie(r,e);)s=de(s),r=s*2;return me(s,t)},this.getRangeEnd=s=>{let r=s*2;for(;!ie(r,e);)s=ue(s,t),r=s*2;return me(s,t)+ye(r,e)};let a=(s,r,o)=>{let c=r*2,l=ie(c,e);if(!s(o,l,r)&&!l){let u=de(r),d=ue(r,t);a(s,u,o+1),a(s,d,o+1)}};this.traverseBuffer=s=>{if(n)throw new Error("BVHTraversalHelper: cannot start a traversal during an active traversal.");n=!0;try{a(s,0,0)}finally{n=!1}},this.traverse=s=>{this.traverseBuffer((r,o,c)=>{if(o){let l=c*2,h=t[c+6],u=e[l+14];return s(r,o,new Float32Array(i,c*4,6),h,u)}else{let l=Es(c,t);return s(r,o,new Float32Array(i,c*4,6),l)}})}}};var Tm=new rn,Ls=new Float32Array(6),Cl=class{constructor(){this._roots=null,this.primitiveBuffer=null,this.primitiveBufferStride=null}init(t){t={...Ml,...t},"maxLeafSize"in t&&(console.warn('BVH: "maxLeafSize" option has been deprecated. Use "targetLeafSize", instead.'),t={...t,targetLeafSize:t.maxLeafSize}),wm(this,t)}getRootRanges(){throw new Error("BVH: getRootRanges() not implemented")}writePrimitiveBounds(){throw new Error("BVH: writePrimitiveBounds() not implemented")}writePrimitiveRangeBounds(t,e,n,a){let s=1/0,r=1/0,o=1/0,c=-1/0,l=-1/0,h=-1/0;for(let u=t,d=t+e;u<d;u++){this.writePrimitiveBounds(u,Ls,0);let[f,x,v,m,g,y]=Ls;f<s&&(s=f),m>c&&(c=m),x<r&&(r=x),g>l&&(l=g),v<o&&(o=v),y>h&&(h=y)}return n[a+0]=s,n[a+1]=r,n[a+2]=o,n[a+3]=c,n[a+4]=l,n[a+5]=h,n}computePrimitiveBounds(t,e,n){let a=n.offset||0;for(let s=t,r=t+e;s<r;s++){this.writePrimitiveBounds(s,Ls,0);let[o,c,l,h,u,d]=Ls,f=(o+h)/2,x=(c+u)/2,v=(l+d)/2,m=(h-o)/2,g=(u-c)/2,y=(d-l)/2,w=(s-a)*6;n[w+0]=f,n[w+1]=m+(Math.abs(f)+m)*As,n[w+2]=x,n[w+3]=g+(Math.abs(x)+g)*As,n[w+4]=v,n[w+5]=y+(Math.abs(v)+y)*As}return n}shiftPrimitiveOffsets(t){let e=this._indirectBuffer;if(e)for(let n=0,a=e.length;n<a;n++)e[n]+=t;else{let n=this._roots;for(let a=0;a<n.length;a++){let s=n[a],r=new Uint32Array(s),o=new Uint16Array(s),c=s.byteLength/32;for(let l=0;l<c;l++){let h=8*l,u=2*h;ie(u,o)&&(r[h+6]+=t)}}}}traverse(t,e=0){Rl.setBVH(this,e),Rl.traverse(t),Rl.reset()}refit(){let t=this._roots;for(let e=0,n=t.length;e<n;e++){let a=t[e],s=new Uint32Array(a),r=new Uint16Array(a),o=new Float32Array(a),c=a.byteLength/32;for(let l=c-1;l>=0;l--){let h=l*8,u=h*2;if(ie(u,r)){let f=me(h,s),x=ye(u,r);this.writePrimitiveRangeBounds(f,x,Ls,0),o.set(Ls,h)}else{let f=de(h),x=ue(h,s);for(let v=0;v<3;v++){let m=o[f+v],g=o[f+v+3],y=o[x+v],w=o[x+v+3];o[h+v]=m<y?m:y,o[h+v+3]=g>w?g:w}}}}}getBoundingBox(t){return t.makeEmpty(),this._roots.forEach(n=>{ve(0,new Float32Array(n),Tm),t.union(Tm)}),t}shapecast(t){let{boundsTraverseOrder:e,intersectsBounds:n,intersectsRange:a,intersectsPrimitive:s,scratchPrimitive:r,iterate:o}=t;if(a&&s){let u=a;a=(d,f,x,v,m)=>u(d,f,x,v,m)?!0:o(d,f,this,s,x,v,r)}else a||(s?a=(u,d,f,x)=>o(u,d,this,s,f,x,r):a=(u,d,f)=>f);let c=!1,l=0,h=this._roots;for(let u=0,d=h.length;u<d;u++){let f=h[u];if(c=Am(this,u,n,a,e,l),c)break;l+=f.byteLength/32}return c}bvhcast(t,e,n){let{intersectsRanges:a}=n;return Em(this,t,e,a)}};function Im(){return typeof SharedArrayBuffer<"u"}function Xd(i){return i.index?i.index.count:i.attributes.position.count}function sa(i){return Xd(i)/3}function nM(i,t=ArrayBuffer){return i>65535?new Uint32Array(new t(4*i)):new Uint16Array(new t(2*i))}function Rm(i,t){if(!i.index){let e=i.attributes.position.count,n=t.useSharedArrayBuffer?SharedArrayBuffer:ArrayBuffer,a=nM(e,n);i.setIndex(new on(a,1));for(let s=0;s<e;s++)a[s]=s}}function iM(i,t,e){let n=Xd(i)/e,a=t||i.drawRange,s=a.start/e,r=(a.start+a.count)/e,o=Math.max(0,s),c=Math.min(n,r)-o;return{offset:Math.floor(o),count:Math.floor(c)}}function aM(i,t){return i.groups.map(e=>({offset:e.start/t,count:e.count/t}))}function qd(i,t,e){let n=iM(i,t,e),a=aM(i,e);if(!a.length)return[n];let s=[],r=n.offset,o=n.offset+n.count,c=Xd(i)/e,l=[];for(let d of a){let{offset:f,count:x}=d,v=f,m=isFinite(x)?x:c-f,g=f+m;v<o&&g>r&&(l.push({pos:Math.max(r,v),isStart:!0}),l.push({pos:Math.min(o,g),isStart:!1}))}l.sort((d,f)=>d.pos!==f.pos?d.pos-f.pos:d.type==="end"?-1:1);let h=0,u=null;for(let d of l){let f=d.pos;h!==0&&f!==u&&s.push({offset:u,count:f-u}),h+=d.isStart?1:-1,u=f}return s}function sM(i,t){let e=i[i.length-1],n=e.offset+e.count>2**16,a=i.reduce((l,h)=>l+h.count,0),s=n?4:2,r=t?new SharedArrayBuffer(a*s):new ArrayBuffer(a*s),o=n?new Uint32Array(r):new Uint16Array(r),c=0;for(let l=0;l<i.length;l++){let{offset:h,count:u}=i[l];for(let d=0;d<u;d++)o[c+d]=h+d;c+=u}return o}var Nl=class extends Cl{get indirect(){return!!this._indirectBuffer}get primitiveStride(){return null}get primitiveBufferStride(){return this.indirect?1:this.primitiveStride}set primitiveBufferStride(t){}get primitiveBuffer(){return this.indirect?this._indirectBuffer:this.geometry.index.array}set primitiveBuffer(t){}constructor(t,e={}){if(t.isBufferGeometry){if(t.index&&t.index.isInterleavedBufferAttribute)throw new Error("BVH: InterleavedBufferAttribute is not supported for the index attribute.")}else throw new Error("BVH: Only BufferGeometries are supported.");if(e.useSharedArrayBuffer&&!Im())throw new Error("BVH: SharedArrayBuffer is not available.");super(),this.geometry=t,this.resolvePrimitiveIndex=e.indirect?n=>this._indirectBuffer[n]:n=>n,this.primitiveBuffer=null,this.primitiveBufferStride=null,this._indirectBuffer=null,e={...Ml,...e},e[Yr]||this.init(e)}init(t){let{geometry:e,primitiveStride:n}=this;if(t.indirect){let a=qd(e,t.range,n),s=sM(a,t.useSharedArrayBuffer);this._indirectBuffer=s}else Rm(e,t);super.init(t),!e.boundingBox&&t.setBoundingBox&&(e.boundingBox=this.getBoundingBox(new rn))}getRootRanges(t){return this.indirect?[{offset:0,count:this._indirectBuffer.length}]:qd(this.geometry,t,this.primitiveStride)}raycastObject3D(){throw new Error("BVH: raycastObject3D() not implemented")}};var Un=class{constructor(){this.min=1/0,this.max=-1/0}setFromPointsField(t,e){let n=1/0,a=-1/0;for(let s=0,r=t.length;s<r;s++){let c=t[s][e];n=c<n?c:n,a=c>a?c:a}this.min=n,this.max=a}setFromPoints(t,e){let n=1/0,a=-1/0;for(let s=0,r=e.length;s<r;s++){let o=e[s],c=t.dot(o);n=c<n?c:n,a=c>a?c:a}this.min=n,this.max=a}isSeparated(t){return this.min>t.max||t.min>this.max}};Un.prototype.setFromBox=(function(){let i=new rt;return function(e,n){let a=n.min,s=n.max,r=1/0,o=-1/0;for(let c=0;c<=1;c++)for(let l=0;l<=1;l++)for(let h=0;h<=1;h++){i.x=a.x*c+s.x*(1-c),i.y=a.y*l+s.y*(1-l),i.z=a.z*h+s.z*(1-h);let u=e.dot(i);r=Math.min(u,r),o=Math.max(u,o)}this.min=r,this.max=o}})();var rM=(function(){let i=new rt,t=new rt,e=new rt;return function(a,s,r){let o=a.start,c=i,l=s.start,h=t;e.subVectors(o,l),i.subVectors(a.end,a.start),t.subVectors(s.end,s.start);let u=e.dot(h),d=h.dot(c),f=h.dot(h),x=e.dot(c),m=c.dot(c)*f-d*d,g,y;m!==0?g=(u*d-x*f)/m:g=0,y=(u+g*d)/f,r.x=g,r.y=y}})(),Zr=(function(){let i=new cn,t=new rt,e=new rt;return function(a,s,r,o){rM(a,s,i);let c=i.x,l=i.y;if(c>=0&&c<=1&&l>=0&&l<=1){a.at(c,r),s.at(l,o);return}else if(c>=0&&c<=1){l<0?s.at(0,o):s.at(1,o),a.closestPointToPoint(o,!0,r);return}else if(l>=0&&l<=1){c<0?a.at(0,r):a.at(1,r),s.closestPointToPoint(r,!0,o);return}else{let h;c<0?h=a.start:h=a.end;let u;l<0?u=s.start:u=s.end;let d=t,f=e;if(a.closestPointToPoint(u,!0,t),s.closestPointToPoint(h,!0,e),d.distanceToSquared(u)<=f.distanceToSquared(h)){r.copy(d),o.copy(u);return}else{r.copy(h),o.copy(f);return}}}})(),Cm=(function(){let i=new rt,t=new rt,e=new Ms,n=new zn;return function(s,r){let{radius:o,center:c}=s,{a:l,b:h,c:u}=r;if(n.start=l,n.end=h,n.closestPointToPoint(c,!0,i).distanceTo(c)<=o||(n.start=l,n.end=u,n.closestPointToPoint(c,!0,i).distanceTo(c)<=o)||(n.start=h,n.end=u,n.closestPointToPoint(c,!0,i).distanceTo(c)<=o))return!0;let v=r.getPlane(e);if(Math.abs(v.distanceToPoint(c))<=o){let g=v.projectPoint(c,t);if(r.containsPoint(g))return!0}return!1}})();var oM=["x","y","z"],Oi=1e-15,Nm=Oi*Oi;function Hn(i){return Math.abs(i)<Oi}var Ke=class extends Ui{constructor(...t){super(...t),this.isExtendedTriangle=!0,this.satAxes=new Array(4).fill().map(()=>new rt),this.satBounds=new Array(4).fill().map(()=>new Un),this.points=[this.a,this.b,this.c],this.plane=new Ms,this.isDegenerateIntoSegment=!1,this.isDegenerateIntoPoint=!1,this.degenerateSegment=new zn,this.needsUpdate=!0}intersectsSphere(t){return Cm(t,this)}update(){let t=this.a,e=this.b,n=this.c,a=this.points,s=this.satAxes,r=this.satBounds,o=s[0],c=r[0];this.getNormal(o),c.setFromPoints(o,a);let l=s[1],h=r[1];l.subVectors(t,e),h.setFromPoints(l,a);let u=s[2],d=r[2];u.subVectors(e,n),d.setFromPoints(u,a);let f=s[3],x=r[3];f.subVectors(n,t),x.setFromPoints(f,a);let v=l.length(),m=u.length(),g=f.length();this.isDegenerateIntoPoint=!1,this.isDegenerateIntoSegment=!1,v<Oi?m<Oi||g<Oi?this.isDegenerateIntoPoint=!0:(this.isDegenerateIntoSegment=!0,this.degenerateSegment.start.copy(t),this.degenerateSegment.end.copy(n)):m<Oi?g<Oi?this.isDegenerateIntoPoint=!0:(this.isDegenerateIntoSegment=!0,this.degenerateSegment.start.copy(e),this.degenerateSegment.end.copy(t)):g<Oi&&(this.isDegenerateIntoSegment=!0,this.degenerateSegment.start.copy(n),this.degenerateSegment.end.copy(e)),this.plane.setFromNormalAndCoplanarPoint(o,t),this.needsUpdate=!1}};Ke.prototype.closestPointToSegment=(function(){let i=new rt,t=new rt,e=new zn;return function(a,s=null,r=null){this.needsUpdate&&this.update();let{start:o,end:c}=a,l=this.points,h,u=1/0,d=this.plane.distanceToPoint(o),f=this.plane.distanceToPoint(c);if(d*f<0&&this.plane.intersectLine(a,i)!==null&&this.containsPoint(i))return s&&s.copy(i),r&&r.copy(i),0;for(let x=0;x<3;x++){let v=(x+1)%3;e.start.copy(l[x]),e.end.copy(l[v]),Zr(e,a,i,t),h=i.distanceToSquared(t),h<u&&(u=h,s&&s.copy(i),r&&r.copy(t))}return this.closestPointToPoint(o,i),h=o.distanceToSquared(i),h<u&&(u=h,s&&s.copy(i),r&&r.copy(o)),this.closestPointToPoint(c,i),h=c.distanceToSquared(i),h<u&&(u=h,s&&s.copy(i),r&&r.copy(c)),Math.sqrt(u)}})();Ke.prototype.intersectsTriangle=(function(){let i=new Ke,t=new Un,e=new Un,n=new rt,a=new rt,s=new rt,r=new rt,o=new zn,c=new zn,l=new rt,h=new cn,u=new cn;function d(w,p,_,S){let b=n;!w.isDegenerateIntoPoint&&!w.isDegenerateIntoSegment?b.copy(w.plane.normal):b.copy(p.plane.normal);let M=w.satBounds,E=w.satAxes;for(let N=1;N<4;N++){let L=M[N],P=E[N];if(t.setFromPoints(P,p.points),L.isSeparated(t)||(r.copy(b).cross(P),t.setFromPoints(r,w.points),e.setFromPoints(r,p.points),t.isSeparated(e)))return!1}let A=p.satBounds,I=p.satAxes;for(let N=1;N<4;N++){let L=A[N],P=I[N];if(t.setFromPoints(P,w.points),L.isSeparated(t)||(r.crossVectors(b,P),t.setFromPoints(r,w.points),e.setFromPoints(r,p.points),t.isSeparated(e)))return!1}return _&&(S||console.warn("ExtendedTriangle.intersectsTriangle: Triangles are coplanar which does not support an output edge. Setting edge to 0, 0, 0."),_.start.set(0,0,0),_.end.set(0,0,0)),!0}function f(w,p,_,S,b,M,E,A,I,N,L){let P=E/(E-A);N.x=S+(b-S)*P,L.start.subVectors(p,w).multiplyScalar(P).add(w),P=E/(E-I),N.y=S+(M-S)*P,L.end.subVectors(_,w).multiplyScalar(P).add(w)}function x(w,p,_,S,b,M,E,A,I,N,L){if(b>0)f(w.c,w.a,w.b,S,p,_,I,E,A,N,L);else if(M>0)f(w.b,w.a,w.c,_,p,S,A,E,I,N,L);else if(A*I>0||E!=0)f(w.a,w.b,w.c,p,_,S,E,A,I,N,L);else if(A!=0)f(w.b,w.a,w.c,_,p,S,A,E,I,N,L);else if(I!=0)f(w.c,w.a,w.b,S,p,_,I,E,A,N,L);else return!0;return!1}function v(w,p,_,S){let b=p.degenerateSegment,M=w.plane.distanceToPoint(b.start),E=w.plane.distanceToPoint(b.end);return Hn(M)?Hn(E)?d(w,p,_,S):(_&&(_.start.copy(b.start),_.end.copy(b.start)),w.containsPoint(b.start)):Hn(E)?(_&&(_.start.copy(b.end),_.end.copy(b.end)),w.containsPoint(b.end)):w.plane.intersectLine(b,n)!=null?(_&&(_.start.copy(n),_.end.copy(n)),w.containsPoint(n)):!1}function m(w,p,_){let S=p.a;return Hn(w.plane.distanceToPoint(S))&&w.containsPoint(S)?(_&&(_.start.copy(S),_.end.copy(S)),!0):!1}function g(w,p,_){let S=w.degenerateSegment,b=p.a;return S.closestPointToPoint(b,!0,n),b.distanceToSquared(n)<Nm?(_&&(_.start.copy(b),_.end.copy(b)),!0):!1}function y(w,p,_,S){if(w.isDegenerateIntoSegment)if(p.isDegenerateIntoSegment){let b=w.degenerateSegment,M=p.degenerateSegment,E=a,A=s;b.delta(E),M.delta(A);let I=n.subVectors(M.start,b.start),N=E.x*A.y-E.y*A.x;if(Hn(N))return!1;let L=(I.x*A.y-I.y*A.x)/N,P=-(E.x*I.y-E.y*I.x)/N;if(L<0||L>1||P<0||P>1)return!1;let U=b.start.z+E.z*L,V=M.start.z+A.z*P;return Hn(U-V)?(_&&(_.start.copy(b.start).addScaledVector(E,L),_.end.copy(b.start).addScaledVector(E,L)),!0):!1}else return p.isDegenerateIntoPoint?g(w,p,_):v(p,w,_,S);else{if(w.isDegenerateIntoPoint)return p.isDegenerateIntoPoint?p.a.distanceToSquared(w.a)<Nm?(_&&(_.start.copy(w.a),_.end.copy(w.a)),!0):!1:p.isDegenerateIntoSegment?g(p,w,_):m(p,w,_);if(p.isDegenerateIntoPoint)return m(w,p,_);if(p.isDegenerateIntoSegment)return v(w,p,_,S)}}return function(p,_=null,S=!1){this.needsUpdate&&this.update(),p.isExtendedTriangle?p.needsUpdate&&p.update():(i.copy(p),i.update(),p=i);let b=y(this,p,_,S);if(b!==void 0)return b;let M=this.plane,E=p.plane,A=E.distanceToPoint(this.a),I=E.distanceToPoint(this.b),N=E.distanceToPoint(this.c);Hn(A)&&(A=0),Hn(I)&&(I=0),Hn(N)&&(N=0);let L=A*I,P=A*N;if(L>0&&P>0)return!1;let U=M.distanceToPoint(p.a),V=M.distanceToPoint(p.b),O=M.distanceToPoint(p.c);Hn(U)&&(U=0),Hn(V)&&(V=0),Hn(O)&&(O=0);let Q=U*V,G=U*O;if(Q>0&&G>0)return!1;a.copy(M.normal),s.copy(E.normal);let Z=a.cross(s),et=0,ht=Math.abs(Z.x),Pt=Math.abs(Z.y);Pt>ht&&(ht=Pt,et=1),Math.abs(Z.z)>ht&&(et=2);let ct=oM[et],mt=this.a[ct],Tt=this.b[ct],gt=this.c[ct],Ot=p.a[ct],ge=p.b[ct],Dt=p.c[ct];if(x(this,mt,Tt,gt,L,P,A,I,N,h,o))return d(this,p,_,S);if(x(p,Ot,ge,Dt,Q,G,U,V,O,u,c))return d(this,p,_,S);if(h.y<h.x){let kt=h.y;h.y=h.x,h.x=kt,l.copy(o.start),o.start.copy(o.end),o.end.copy(l)}if(u.y<u.x){let kt=u.y;u.y=u.x,u.x=kt,l.copy(c.start),c.start.copy(c.end),c.end.copy(l)}return h.y<u.x||u.y<h.x?!1:(_&&(u.x>h.x?_.start.copy(c.start):_.start.copy(o.start),u.y<h.y?_.end.copy(c.end):_.end.copy(o.end)),!0)}})();Ke.prototype.distanceToPoint=(function(){let i=new rt;return function(e){return this.closestPointToPoint(e,i),e.distanceTo(i)}})();Ke.prototype.distanceToTriangle=(function(){let i=new rt,t=new rt,e=["a","b","c"],n=new zn,a=new zn;return function(r,o=null,c=null){let l=o||c?n:null;if(this.intersectsTriangle(r,l,!0))return(o||c)&&(o&&l.getCenter(o),c&&l.getCenter(c)),0;let h=1/0;for(let u=0;u<3;u++){let d,f=e[u],x=r[f];this.closestPointToPoint(x,i),d=x.distanceToSquared(i),d<h&&(h=d,o&&o.copy(i),c&&c.copy(x));let v=this[f];r.closestPointToPoint(v,i),d=v.distanceToSquared(i),d<h&&(h=d,o&&o.copy(v),c&&c.copy(i))}for(let u=0;u<3;u++){let d=e[u],f=e[(u+1)%3];n.set(this[d],this[f]);for(let x=0;x<3;x++){let v=e[x],m=e[(x+1)%3];a.set(r[v],r[m]),Zr(n,a,i,t);let g=i.distanceToSquared(t);g<h&&(h=g,o&&o.copy(i),c&&c.copy(t))}}return Math.sqrt(h)}})();var Re=class{constructor(t,e,n){this.isOrientedBox=!0,this.min=new rt,this.max=new rt,this.matrix=new Je,this.invMatrix=new Je,this.points=new Array(8).fill().map(()=>new rt),this.satAxes=new Array(3).fill().map(()=>new rt),this.satBounds=new Array(3).fill().map(()=>new Un),this.alignedSatBounds=new Array(3).fill().map(()=>new Un),this.needsUpdate=!1,t&&this.min.copy(t),e&&this.max.copy(e),n&&this.matrix.copy(n)}set(t,e,n){this.min.copy(t),this.max.copy(e),this.matrix.copy(n),this.needsUpdate=!0}copy(t){this.min.copy(t.min),this.max.copy(t.max),this.matrix.copy(t.matrix),this.needsUpdate=!0}};Re.prototype.update=(function(){return function(){let t=this.matrix,e=this.min,n=this.max,a=this.points;for(let l=0;l<=1;l++)for(let h=0;h<=1;h++)for(let u=0;u<=1;u++){let d=1*l|2*h|4*u,f=a[d];f.x=l?n.x:e.x,f.y=h?n.y:e.y,f.z=u?n.z:e.z,f.applyMatrix4(t)}let s=this.satBounds,r=this.satAxes,o=a[0];for(let l=0;l<3;l++){let h=r[l],u=s[l],d=1<<l,f=a[d];h.subVectors(o,f),u.setFromPoints(h,a)}let c=this.alignedSatBounds;c[0].setFromPointsField(a,"x"),c[1].setFromPointsField(a,"y"),c[2].setFromPointsField(a,"z"),this.invMatrix.copy(this.matrix).invert(),this.needsUpdate=!1}})();Re.prototype.intersectsBox=(function(){let i=new Un;return function(e){this.needsUpdate&&this.update();let n=e.min,a=e.max,s=this.satBounds,r=this.satAxes,o=this.alignedSatBounds;if(i.min=n.x,i.max=a.x,o[0].isSeparated(i)||(i.min=n.y,i.max=a.y,o[1].isSeparated(i))||(i.min=n.z,i.max=a.z,o[2].isSeparated(i)))return!1;for(let c=0;c<3;c++){let l=r[c],h=s[c];if(i.setFromBox(l,e),h.isSeparated(i))return!1}return!0}})();Re.prototype.intersectsTriangle=(function(){let i=new Ke,t=new Array(3),e=new Un,n=new Un,a=new rt;return function(r){this.needsUpdate&&this.update(),r.isExtendedTriangle?r.needsUpdate&&r.update():(i.copy(r),i.update(),r=i);let o=this.satBounds,c=this.satAxes;t[0]=r.a,t[1]=r.b,t[2]=r.c;for(let d=0;d<3;d++){let f=o[d],x=c[d];if(e.setFromPoints(x,t),f.isSeparated(e))return!1}let l=r.satBounds,h=r.satAxes,u=this.points;for(let d=0;d<3;d++){let f=l[d],x=h[d];if(e.setFromPoints(x,u),f.isSeparated(e))return!1}for(let d=0;d<3;d++){let f=c[d];for(let x=0;x<4;x++){let v=h[x];if(a.crossVectors(f,v),e.setFromPoints(a,t),n.setFromPoints(a,u),e.isSeparated(n))return!1}}return!0}})();Re.prototype.closestPointToPoint=(function(){return function(t,e){return this.needsUpdate&&this.update(),e.copy(t).applyMatrix4(this.invMatrix).clamp(this.min,this.max).applyMatrix4(this.matrix),e}})();Re.prototype.distanceToPoint=(function(){let i=new rt;return function(e){return this.closestPointToPoint(e,i),e.distanceTo(i)}})();Re.prototype.distanceToBox=(function(){let i=["x","y","z"],t=new Array(12).fill().map(()=>new zn),e=new Array(12).fill().map(()=>new zn),n=new rt,a=new rt;return function(r,o=0,c=null,l=null){if(this.needsUpdate&&this.update(),this.intersectsBox(r))return(c||l)&&(r.getCenter(a),this.closestPointToPoint(a,n),r.closestPointToPoint(n,a),c&&c.copy(n),l&&l.copy(a)),0;let h=o*o,u=r.min,d=r.max,f=this.points,x=1/0;for(let m=0;m<8;m++){let g=f[m];a.copy(g).clamp(u,d);let y=g.distanceToSquared(a);if(y<x&&(x=y,c&&c.copy(g),l&&l.copy(a),y<h))return Math.sqrt(y)}let v=0;for(let m=0;m<3;m++)for(let g=0;g<=1;g++)for(let y=0;y<=1;y++){let w=(m+1)%3,p=(m+2)%3,_=g<<w|y<<p,S=1<<m|g<<w|y<<p,b=f[_],M=f[S];t[v].set(b,M);let A=i[m],I=i[w],N=i[p],L=e[v],P=L.start,U=L.end;P[A]=u[A],P[I]=g?u[I]:d[I],P[N]=y?u[N]:d[N],U[A]=d[A],U[I]=g?u[I]:d[I],U[N]=y?u[N]:d[N],v++}for(let m=0;m<=1;m++)for(let g=0;g<=1;g++)for(let y=0;y<=1;y++){a.x=m?d.x:u.x,a.y=g?d.y:u.y,a.z=y?d.z:u.z,this.closestPointToPoint(a,n);let w=a.distanceToSquared(n);if(w<x&&(x=w,c&&c.copy(n),l&&l.copy(a),w<h))return Math.sqrt(w)}for(let m=0;m<12;m++){let g=t[m];for(let y=0;y<12;y++){let w=e[y];Zr(g,w,n,a);let p=n.distanceToSquared(a);if(p<x&&(x=p,c&&c.copy(n),l&&l.copy(a),p<h))return Math.sqrt(p)}}return Math.sqrt(x)}})();var Yd=class extends na{constructor(){super(()=>new Ke)}},Mn=new Yd;var Qr=new rt,Jd=new rt;function Pm(i,t,e={},n=0,a=1/0){let s=n*n,r=a*a,o=1/0,c=null;if(i.shapecast({boundsTraverseOrder:h=>(Qr.copy(t).clamp(h.min,h.max),Qr.distanceToSquared(t)),intersectsBounds:(h,u,d)=>d<o&&d<r,intersectsTriangle:(h,u)=>{h.closestPointToPoint(t,Qr);let d=t.distanceToSquared(Qr);return d<o&&(Jd.copy(Qr),o=d,c=u),d<s}}),o===1/0)return null;let l=Math.sqrt(o);return e.point?e.point.copy(Jd):e.point=Jd.clone(),e.distance=l,e.faceIndex=c,e}var Pl=parseInt(Cd)>=169,cM=parseInt(Cd)<=161,Ia=new rt,Ra=new rt,Ca=new rt,Ll=new cn,Dl=new cn,Ul=new cn,Lm=new rt,Dm=new rt,Um=new rt,$r=new rt;function lM(i,t,e,n,a,s,r,o){let c;if(s===ul?c=i.intersectTriangle(n,e,t,!0,a):c=i.intersectTriangle(t,e,n,s!==Zi,a),c===null)return null;let l=i.origin.distanceTo(a);return l<r||l>o?null:{distance:l,point:a.clone()}}function Om(i,t,e,n,a,s,r,o,c,l,h){Ia.fromBufferAttribute(t,s),Ra.fromBufferAttribute(t,r),Ca.fromBufferAttribute(t,o);let u=lM(i,Ia,Ra,Ca,$r,c,l,h);if(u){if(n){Ll.fromBufferAttribute(n,s),Dl.fromBufferAttribute(n,r),Ul.fromBufferAttribute(n,o),u.uv=new cn;let f=Ui.getInterpolation($r,Ia,Ra,Ca,Ll,Dl,Ul,u.uv);Pl||(u.uv=f)}if(a){Ll.fromBufferAttribute(a,s),Dl.fromBufferAttribute(a,r),Ul.fromBufferAttribute(a,o),u.uv1=new cn;let f=Ui.getInterpolation($r,Ia,Ra,Ca,Ll,Dl,Ul,u.uv1);Pl||(u.uv1=f),cM&&(u.uv2=u.uv1)}if(e){Lm.fromBufferAttribute(e,s),Dm.fromBufferAttribute(e,r),Um.fromBufferAttribute(e,o),u.normal=new rt;let f=Ui.getInterpolation($r,Ia,Ra,Ca,Lm,Dm,Um,u.normal);u.normal.dot(i.direction)>0&&u.normal.multiplyScalar(-1),Pl||(u.normal=f)}let d={a:s,b:r,c:o,normal:new rt,materialIndex:0};if(Ui.getNormal(Ia,Ra,Ca,d.normal),u.face=d,u.faceIndex=s,Pl){let f=new rt;Ui.getBarycoord($r,Ia,Ra,Ca,f),u.barycoord=f}}return u}function Fm(i){return i&&i.isMaterial?i.side:i}function Ds(i,t,e,n,a,s,r){let o=n*3,c=o+0,l=o+1,h=o+2,{index:u,groups:d}=i;i.index&&(c=u.getX(c),l=u.getX(l),h=u.getX(h));let{position:f,normal:x,uv:v,uv1:m}=i.attributes;if(Array.isArray(t)){let g=n*3;for(let y=0,w=d.length;y<w;y++){let{start:p,count:_,materialIndex:S}=d[y];if(g>=p&&g<p+_){let b=Fm(t[S]),M=Om(e,f,x,v,m,c,l,h,b,s,r);if(M)if(M.faceIndex=n,M.face.materialIndex=S,a)a.push(M);else return M}}}else{let g=Fm(t),y=Om(e,f,x,v,m,c,l,h,g,s,r);if(y)if(y.faceIndex=n,y.face.materialIndex=0,a)a.push(y);else return y}return null}function Me(i,t,e,n){let a=i.a,s=i.b,r=i.c,o=t,c=t+1,l=t+2;e&&(o=e.getX(o),c=e.getX(c),l=e.getX(l)),a.x=n.getX(o),a.y=n.getY(o),a.z=n.getZ(o),s.x=n.getX(c),s.y=n.getY(c),s.z=n.getZ(c),r.x=n.getX(l),r.y=n.getY(l),r.z=n.getZ(l)}function Bm(i,t,e,n,a,s,r,o){let{geometry:c,_indirectBuffer:l}=i;for(let h=n,u=n+a;h<u;h++)Ds(c,t,e,h,s,r,o)}function km(i,t,e,n,a,s,r){let{geometry:o,_indirectBuffer:c}=i,l=1/0,h=null;for(let u=n,d=n+a;u<d;u++){let f;f=Ds(o,t,e,u,null,s,r),f&&f.distance<l&&(h=f,l=f.distance)}return h}function zm(i,t,e,n,a,s,r){let{geometry:o}=e,{index:c}=o,l=o.attributes.position;for(let h=i,u=t+i;h<u;h++){let d;if(d=h,Me(r,d*3,c,l),r.needsUpdate=!0,n(r,d,a,s))return!0}return!1}function Vm(i,t=null){t&&Array.isArray(t)&&(t=new Set(t));let e=i.geometry,n=e.index?e.index.array:null,a=e.attributes.position,s,r,o,c,l=0,h=i._roots;for(let d=0,f=h.length;d<f;d++)s=h[d],r=new Uint32Array(s),o=new Uint16Array(s),c=new Float32Array(s),u(0,l),l+=s.byteLength;function u(d,f,x=!1){let v=d*2;if(ie(v,o)){let m=me(d,r),g=ye(v,o),y=1/0,w=1/0,p=1/0,_=-1/0,S=-1/0,b=-1/0;for(let M=3*m,E=3*(m+g);M<E;M++){let A=n[M],I=a.getX(A),N=a.getY(A),L=a.getZ(A);I<y&&(y=I),I>_&&(_=I),N<w&&(w=N),N>S&&(S=N),L<p&&(p=L),L>b&&(b=L)}return c[d+0]!==y||c[d+1]!==w||c[d+2]!==p||c[d+3]!==_||c[d+4]!==S||c[d+5]!==b?(c[d+0]=y,c[d+1]=w,c[d+2]=p,c[d+3]=_,c[d+4]=S,c[d+5]=b,!0):!1}else{let m=de(d),g=ue(d,r),y=x,w=!1,p=!1;if(t){if(!y){let A=m/8+f/32,I=g/8+f/32;w=t.has(A),p=t.has(I),y=!w&&!p}}else w=!0,p=!0;let _=y||w,S=y||p,b=!1;_&&(b=u(m,f,y));let M=!1;S&&(M=u(g,f,y));let E=b||M;if(E)for(let A=0;A<3;A++){let I=m+A,N=g+A,L=c[I],P=c[I+3],U=c[N],V=c[N+3];c[d+A]=L<U?L:U,c[d+A+3]=P>V?P:V}return E}}}function ln(i,t,e,n,a){let s,r,o,c,l,h,u=1/e.direction.x,d=1/e.direction.y,f=1/e.direction.z,x=e.origin.x,v=e.origin.y,m=e.origin.z,g=t[i],y=t[i+3],w=t[i+1],p=t[i+3+1],_=t[i+2],S=t[i+3+2];return u>=0?(s=(g-x)*u,r=(y-x)*u):(s=(y-x)*u,r=(g-x)*u),d>=0?(o=(w-v)*d,c=(p-v)*d):(o=(p-v)*d,c=(w-v)*d),s>c||o>r||((o>s||isNaN(s))&&(s=o),(c<r||isNaN(r))&&(r=c),f>=0?(l=(_-m)*f,h=(S-m)*f):(l=(S-m)*f,h=(_-m)*f),s>h||l>r)?!1:((l>s||s!==s)&&(s=l),(h<r||r!==r)&&(r=h),s<=a&&r>=n)}function Hm(i,t,e,n,a,s,r,o){let{geometry:c,_indirectBuffer:l}=i;for(let h=n,u=n+a;h<u;h++){let d=l?l[h]:h;Ds(c,t,e,d,s,r,o)}}function Gm(i,t,e,n,a,s,r){let{geometry:o,_indirectBuffer:c}=i,l=1/0,h=null;for(let u=n,d=n+a;u<d;u++){let f;f=Ds(o,t,e,c?c[u]:u,null,s,r),f&&f.distance<l&&(h=f,l=f.distance)}return h}function Wm(i,t,e,n,a,s,r){let{geometry:o}=e,{index:c}=o,l=o.attributes.position;for(let h=i,u=t+i;h<u;h++){let d;if(d=e.resolveTriangleIndex(h),Me(r,d*3,c,l),r.needsUpdate=!0,n(r,d,a,s))return!0}return!1}function jm(i,t,e,n,a,s,r){Zt.setBuffer(i._roots[t]),ln(0,Zt.float32Array,n,s,r)&&Kd(0,i,e,n,a,s,r),Zt.clearBuffer()}function Kd(i,t,e,n,a,s,r){let{float32Array:o,uint16Array:c,uint32Array:l}=Zt,h=i*2;if(ie(h,c)){let d=me(i,l),f=ye(h,c);Bm(t,e,n,d,f,a,s,r)}else{let d=de(i);ln(d,o,n,s,r)&&Kd(d,t,e,n,a,s,r);let f=ue(i,l);ln(f,o,n,s,r)&&Kd(f,t,e,n,a,s,r)}}var hM=["x","y","z"];function Xm(i,t,e,n,a,s){Zt.setBuffer(i._roots[t]);let r=null;return ln(0,Zt.float32Array,n,a,s)&&(r=Zd(0,i,e,n,a,s)),Zt.clearBuffer(),r}function Zd(i,t,e,n,a,s){let{float32Array:r,uint16Array:o,uint32Array:c}=Zt,l=i*2;if(ie(l,o)){let u=me(i,c),d=ye(l,o);return km(t,e,n,u,d,a,s)}else{let u=Es(i,c),d=hM[u],x=n.direction[d]>=0,v,m;x?(v=de(i),m=ue(i,c)):(v=ue(i,c),m=de(i));let y=ln(v,r,n,a,s)?Zd(v,t,e,n,a,s):null;if(y){let _=y.point[d];if(x?_<=r[m+u]:_>=r[m+u+3])return y}let p=ln(m,r,n,a,s)?Zd(m,t,e,n,a,s):null;return y&&p?y.distance<=p.distance?y:p:y||p||null}}var Ol=new rn,Us=new Ke,Os=new Ke,to=new Je,qm=new Re,Fl=new Re;function Ym(i,t,e,n){Zt.setBuffer(i._roots[t]);let a=Qd(0,i,e,n);return Zt.clearBuffer(),a}function Qd(i,t,e,n,a=null){let{float32Array:s,uint16Array:r,uint32Array:o}=Zt,c=i*2;if(a===null&&(e.boundingBox||e.computeBoundingBox(),qm.set(e.boundingBox.min,e.boundingBox.max,n),a=qm),ie(c,r)){let h=t.geometry,u=h.index,d=h.attributes.position,f=e.index,x=e.attributes.position,v=me(i,o),m=ye(c,r);if(to.copy(n).invert(),e.boundsTree)return ve(i,s,Fl),Fl.matrix.copy(to),Fl.needsUpdate=!0,e.boundsTree.shapecast({intersectsBounds:y=>Fl.intersectsBox(y),intersectsTriangle:y=>{y.a.applyMatrix4(n),y.b.applyMatrix4(n),y.c.applyMatrix4(n),y.needsUpdate=!0;for(let w=v*3,p=(m+v)*3;w<p;w+=3)if(Me(Os,w,u,d),Os.needsUpdate=!0,y.intersectsTriangle(Os))return!0;return!1}});{let g=sa(e);for(let y=v*3,w=(m+v)*3;y<w;y+=3){Me(Us,y,u,d),Us.a.applyMatrix4(to),Us.b.applyMatrix4(to),Us.c.applyMatrix4(to),Us.needsUpdate=!0;for(let p=0,_=g*3;p<_;p+=3)if(Me(Os,p,f,x),Os.needsUpdate=!0,Us.intersectsTriangle(Os))return!0}}}else{let h=de(i),u=ue(i,o);return ve(h,s,Ol),!!(a.intersectsBox(Ol)&&Qd(h,t,e,n,a)||(ve(u,s,Ol),a.intersectsBox(Ol)&&Qd(u,t,e,n,a)))}}var Bl=new Je,$d=new Re,eo=new Re,dM=new rt,uM=new rt,fM=new rt,pM=new rt;function Jm(i,t,e,n={},a={},s=0,r=1/0){t.boundingBox||t.computeBoundingBox(),$d.set(t.boundingBox.min,t.boundingBox.max,e),$d.needsUpdate=!0;let o=i.geometry,c=o.attributes.position,l=o.index,h=t.attributes.position,u=t.index,d=Mn.getPrimitive(),f=Mn.getPrimitive(),x=dM,v=uM,m=null,g=null;a&&(m=fM,g=pM);let y=1/0,w=null,p=null;return Bl.copy(e).invert(),eo.matrix.copy(Bl),i.shapecast({boundsTraverseOrder:_=>$d.distanceToBox(_),intersectsBounds:(_,S,b)=>b<y&&b<r?(S&&(eo.min.copy(_.min),eo.max.copy(_.max),eo.needsUpdate=!0),!0):!1,intersectsRange:(_,S)=>{if(t.boundsTree)return t.boundsTree.shapecast({boundsTraverseOrder:M=>eo.distanceToBox(M),intersectsBounds:(M,E,A)=>A<y&&A<r,intersectsRange:(M,E)=>{for(let A=M,I=M+E;A<I;A++){Me(f,3*A,u,h),f.a.applyMatrix4(e),f.b.applyMatrix4(e),f.c.applyMatrix4(e),f.needsUpdate=!0;for(let N=_,L=_+S;N<L;N++){Me(d,3*N,l,c),d.needsUpdate=!0;let P=d.distanceToTriangle(f,x,m);if(P<y&&(v.copy(x),g&&g.copy(m),y=P,w=N,p=A),P<s)return!0}}}});{let b=sa(t);for(let M=0,E=b;M<E;M++){Me(f,3*M,u,h),f.a.applyMatrix4(e),f.b.applyMatrix4(e),f.c.applyMatrix4(e),f.needsUpdate=!0;for(let A=_,I=_+S;A<I;A++){Me(d,3*A,l,c),d.needsUpdate=!0;let N=d.distanceToTriangle(f,x,m);if(N<y&&(v.copy(x),g&&g.copy(m),y=N,w=A,p=M),N<s)return!0}}}}}),Mn.releasePrimitive(d),Mn.releasePrimitive(f),y===1/0?null:(n.point?n.point.copy(v):n.point=v.clone(),n.distance=y,n.faceIndex=w,a&&(a.point?a.point.copy(g):a.point=g.clone(),a.point.applyMatrix4(Bl),v.applyMatrix4(Bl),a.distance=v.sub(a.point).length(),a.faceIndex=p),n)}function Km(i,t=null){t&&Array.isArray(t)&&(t=new Set(t));let e=i.geometry,n=e.index?e.index.array:null,a=e.attributes.position,s,r,o,c,l=0,h=i._roots;for(let d=0,f=h.length;d<f;d++)s=h[d],r=new Uint32Array(s),o=new Uint16Array(s),c=new Float32Array(s),u(0,l),l+=s.byteLength;function u(d,f,x=!1){let v=d*2;if(ie(v,o)){let m=me(d,r),g=ye(v,o),y=1/0,w=1/0,p=1/0,_=-1/0,S=-1/0,b=-1/0;for(let M=m,E=m+g;M<E;M++){let A=3*i.resolveTriangleIndex(M);for(let I=0;I<3;I++){let N=A+I;N=n?n[N]:N;let L=a.getX(N),P=a.getY(N),U=a.getZ(N);L<y&&(y=L),L>_&&(_=L),P<w&&(w=P),P>S&&(S=P),U<p&&(p=U),U>b&&(b=U)}}return c[d+0]!==y||c[d+1]!==w||c[d+2]!==p||c[d+3]!==_||c[d+4]!==S||c[d+5]!==b?(c[d+0]=y,c[d+1]=w,c[d+2]=p,c[d+3]=_,c[d+4]=S,c[d+5]=b,!0):!1}else{let m=de(d),g=ue(d,r),y=x,w=!1,p=!1;if(t){if(!y){let A=m/8+f/32,I=g/8+f/32;w=t.has(A),p=t.has(I),y=!w&&!p}}else w=!0,p=!0;let _=y||w,S=y||p,b=!1;_&&(b=u(m,f,y));let M=!1;S&&(M=u(g,f,y));let E=b||M;if(E)for(let A=0;A<3;A++){let I=m+A,N=g+A,L=c[I],P=c[I+3],U=c[N],V=c[N+3];c[d+A]=L<U?L:U,c[d+A+3]=P>V?P:V}return E}}}function Zm(i,t,e,n,a,s,r){Zt.setBuffer(i._roots[t]),ln(0,Zt.float32Array,n,s,r)&&tu(0,i,e,n,a,s,r),Zt.clearBuffer()}function tu(i,t,e,n,a,s,r){let{float32Array:o,uint16Array:c,uint32Array:l}=Zt,h=i*2;if(ie(h,c)){let d=me(i,l),f=ye(h,c);Hm(t,e,n,d,f,a,s,r)}else{let d=de(i);ln(d,o,n,s,r)&&tu(d,t,e,n,a,s,r);let f=ue(i,l);ln(f,o,n,s,r)&&tu(f,t,e,n,a,s,r)}}var mM=["x","y","z"];function Qm(i,t,e,n,a,s){Zt.setBuffer(i._roots[t]);let r=null;return ln(0,Zt.float32Array,n,a,s)&&(r=eu(0,i,e,n,a,s)),Zt.clearBuffer(),r}function eu(i,t,e,n,a,s){let{float32Array:r,uint16Array:o,uint32Array:c}=Zt,l=i*2;if(ie(l,o)){let u=me(i,c),d=ye(l,o);return Gm(t,e,n,u,d,a,s)}else{let u=Es(i,c),d=mM[u],x=n.direction[d]>=0,v,m;x?(v=de(i),m=ue(i,c)):(v=ue(i,c),m=de(i));let y=ln(v,r,n,a,s)?eu(v,t,e,n,a,s):null;if(y){let _=y.point[d];if(x?_<=r[m+u]:_>=r[m+u+3])return y}let p=ln(m,r,n,a,s)?eu(m,t,e,n,a,s):null;return y&&p?y.distance<=p.distance?y:p:y||p||null}}var kl=new rn,Fs=new Ke,Bs=new Ke,no=new Je,$m=new Re,zl=new Re;function tg(i,t,e,n){Zt.setBuffer(i._roots[t]);let a=nu(0,i,e,n);return Zt.clearBuffer(),a}function nu(i,t,e,n,a=null){let{float32Array:s,uint16Array:r,uint32Array:o}=Zt,c=i*2;if(a===null&&(e.boundingBox||e.computeBoundingBox(),$m.set(e.boundingBox.min,e.boundingBox.max,n),a=$m),ie(c,r)){let h=t.geometry,u=h.index,d=h.attributes.position,f=e.index,x=e.attributes.position,v=me(i,o),m=ye(c,r);if(no.copy(n).invert(),e.boundsTree)return ve(i,s,zl),zl.matrix.copy(no),zl.needsUpdate=!0,e.boundsTree.shapecast({intersectsBounds:y=>zl.intersectsBox(y),intersectsTriangle:y=>{y.a.applyMatrix4(n),y.b.applyMatrix4(n),y.c.applyMatrix4(n),y.needsUpdate=!0;for(let w=v,p=m+v;w<p;w++)if(Me(Bs,3*t.resolveTriangleIndex(w),u,d),Bs.needsUpdate=!0,y.intersectsTriangle(Bs))return!0;return!1}});{let g=sa(e);for(let y=v,w=m+v;y<w;y++){let p=t.resolveTriangleIndex(y);Me(Fs,3*p,u,d),Fs.a.applyMatrix4(no),Fs.b.applyMatrix4(no),Fs.c.applyMatrix4(no),Fs.needsUpdate=!0;for(let _=0,S=g*3;_<S;_+=3)if(Me(Bs,_,f,x),Bs.needsUpdate=!0,Fs.intersectsTriangle(Bs))return!0}}}else{let h=de(i),u=ue(i,o);return ve(h,s,kl),!!(a.intersectsBox(kl)&&nu(h,t,e,n,a)||(ve(u,s,kl),a.intersectsBox(kl)&&nu(u,t,e,n,a)))}}var Vl=new Je,iu=new Re,io=new Re,gM=new rt,bM=new rt,xM=new rt,yM=new rt;function eg(i,t,e,n={},a={},s=0,r=1/0){t.boundingBox||t.computeBoundingBox(),iu.set(t.boundingBox.min,t.boundingBox.max,e),iu.needsUpdate=!0;let o=i.geometry,c=o.attributes.position,l=o.index,h=t.attributes.position,u=t.index,d=Mn.getPrimitive(),f=Mn.getPrimitive(),x=gM,v=bM,m=null,g=null;a&&(m=xM,g=yM);let y=1/0,w=null,p=null;return Vl.copy(e).invert(),io.matrix.copy(Vl),i.shapecast({boundsTraverseOrder:_=>iu.distanceToBox(_),intersectsBounds:(_,S,b)=>b<y&&b<r?(S&&(io.min.copy(_.min),io.max.copy(_.max),io.needsUpdate=!0),!0):!1,intersectsRange:(_,S)=>{if(t.boundsTree){let b=t.boundsTree;return b.shapecast({boundsTraverseOrder:M=>io.distanceToBox(M),intersectsBounds:(M,E,A)=>A<y&&A<r,intersectsRange:(M,E)=>{for(let A=M,I=M+E;A<I;A++){let N=b.resolveTriangleIndex(A);Me(f,3*N,u,h),f.a.applyMatrix4(e),f.b.applyMatrix4(e),f.c.applyMatrix4(e),f.needsUpdate=!0;for(let L=_,P=_+S;L<P;L++){let U=i.resolveTriangleIndex(L);Me(d,3*U,l,c),d.needsUpdate=!0;let V=d.distanceToTriangle(f,x,m);if(V<y&&(v.copy(x),g&&g.copy(m),y=V,w=L,p=A),V<s)return!0}}}})}else{let b=sa(t);for(let M=0,E=b;M<E;M++){Me(f,3*M,u,h),f.a.applyMatrix4(e),f.b.applyMatrix4(e),f.c.applyMatrix4(e),f.needsUpdate=!0;for(let A=_,I=_+S;A<I;A++){let N=i.resolveTriangleIndex(A);Me(d,3*N,l,c),d.needsUpdate=!0;let L=d.distanceToTriangle(f,x,m);if(L<y&&(v.copy(x),g&&g.copy(m),y=L,w=A,p=M),L<s)return!0}}}}}),Mn.releasePrimitive(d),Mn.releasePrimitive(f),y===1/0?null:(n.point?n.point.copy(v):n.point=v.clone(),n.distance=y,n.faceIndex=w,a&&(a.point?a.point.copy(g):a.point=g.clone(),a.point.applyMatrix4(Vl),v.applyMatrix4(Vl),a.distance=v.sub(a.point).length(),a.faceIndex=p),n)}function au(i,t,e){return i===null?null:(i.point.applyMatrix4(t.matrixWorld),i.distance=i.point.distanceTo(e.ray.origin),i.object=t,i)}var Hl=new Re,Gl=new kp,ng=new rt,ig=new Je,ag=new rt,su=["getX","getY","getZ"],Wl=class i extends Nl{static serialize(t,e={}){e={cloneBuffers:!0,...e};let n=t.geometry,a=t._roots,s=t._indirectBuffer,r=n.getIndex(),o={version:1,roots:null,index:null,indirectBuffer:null};return e.cloneBuffers?(o.roots=a.map(c=>c.slice()),o.index=r?r.array.slice():null,o.indirectBuffer=s?s.slice():null):(o.roots=a,o.index=r?r.array:null,o.indirectBuffer=s),o}static deserialize(t,e,n={}){n={setIndex:!0,indirect:!!t.indirectBuffer,...n};let{index:a,roots:s,indirectBuffer:r}=t;t.version||(console.warn("MeshBVH.deserialize: Serialization format has been changed and will be fixed up. It is recommended to regenerate any stored serialized data."),c(s));let o=new i(e,{...n,[Yr]:!0});if(o._roots=s,o._indirectBuffer=r||null,n.setIndex){let l=e.getIndex();if(l===null){let h=new on(t.index,1,!1);e.setIndex(h)}else l.array!==a&&(l.array.set(a),l.needsUpdate=!0)}return o;function c(l){for(let h=0;h<l.length;h++){let u=l[h],d=new Uint32Array(u),f=new Uint16Array(u);for(let x=0,v=u.byteLength/32;x<v;x++){let m=8*x,g=2*m;ie(g,f)||(d[m+6]=d[m+6]/8-x)}}}}get primitiveStride(){return 3}get resolveTriangleIndex(){return this.resolvePrimitiveIndex}constructor(t,e={}){e.maxLeafTris&&(console.warn('MeshBVH: "maxLeafTris" option has been deprecated. Use "targetLeafSize", instead.'),e={...e,targetLeafSize:e.maxLeafTris}),super(t,e)}shiftTriangleOffsets(t){return super.shiftPrimitiveOffsets(t)}writePrimitiveBounds(t,e,n){let a=this.geometry,s=this._indirectBuffer,r=a.attributes.position,o=a.index?a.index.array:null,l=(s?s[t]:t)*3,h=l+0,u=l+1,d=l+2;o&&(h=o[h],u=o[u],d=o[d]);for(let f=0;f<3;f++){let x=r[su[f]](h),v=r[su[f]](u),m=r[su[f]](d),g=x;v<g&&(g=v),m<g&&(g=m);let y=x;v>y&&(y=v),m>y&&(y=m),e[n+f]=g,e[n+f+3]=y}return e}computePrimitiveBounds(t,e,n){let a=this.geometry,s=this._indirectBuffer,r=a.attributes.position,o=a.index?a.index.array:null,c=r.normalized;if(t<0||e+t-n.offset>n.length/6)throw new Error("MeshBVH: compute triangle bounds range is invalid.");let l=r.array,h=r.offset||0,u=3;r.isInterleavedBufferAttribute&&(u=r.data.stride);let d=["getX","getY","getZ"],f=n.offset;for(let x=t,v=t+e;x<v;x++){let g=(s?s[x]:x)*3,y=(x-f)*6,w=g+0,p=g+1,_=g+2;o&&(w=o[w],p=o[p],_=o[_]),c||(w=w*u+h,p=p*u+h,_=_*u+h);for(let S=0;S<3;S++){let b,M,E;c?(b=r[d[S]](w),M=r[d[S]](p),E=r[d[S]](_)):(b=l[w+S],M=l[p+S],E=l[_+S]);let A=b;M<A&&(A=M),E<A&&(A=E);let I=b;M>I&&(I=M),E>I&&(I=E);let N=(I-A)/2,L=S*2;n[y+L+0]=A+N,n[y+L+1]=N+(Math.abs(A)+N)*As}}return n}raycastObject3D(t,e,n=[]){let{material:a}=t;if(a===void 0)return;ig.copy(t.matrixWorld).invert(),Gl.copy(e.ray).applyMatrix4(ig),ag.setFromMatrixScale(t.matrixWorld),ng.copy(Gl.direction).multiply(ag);let s=ng.length(),r=e.near/s,o=e.far/s;if(e.firstHitOnly===!0){let c=this.raycastFirst(Gl,a,r,o);c=au(c,t,e),c&&n.push(c)}else{let c=this.raycast(Gl,a,r,o);for(let l=0,h=c.length;l<h;l++){let u=au(c[l],t,e);u&&n.push(u)}}return n}refit(t=null){return(this.indirect?Km:Vm)(this,t)}raycast(t,e=Di,n=0,a=1/0){let s=this._roots,r=[],o=this.indirect?Zm:jm;for(let c=0,l=s.length;c<l;c++)o(this,c,e,t,r,n,a);return r}raycastFirst(t,e=Di,n=0,a=1/0){let s=this._roots,r=null,o=this.indirect?Qm:Xm;for(let c=0,l=s.length;c<l;c++){let h=o(this,c,e,t,n,a);h!=null&&(r==null||h.distance<r.distance)&&(r=h)}return r}intersectsGeometry(t,e){let n=!1,a=this._roots,s=this.indirect?tg:Ym;for(let r=0,o=a.length;r<o&&(n=s(this,r,t,e),!n);r++);return n}shapecast(t){let e=Mn.getPrimitive(),n=super.shapecast({...t,intersectsPrimitive:t.intersectsTriangle,scratchPrimitive:e,iterate:this.indirect?Wm:zm});return Mn.releasePrimitive(e),n}bvhcast(t,e,n){let{intersectsRanges:a,intersectsTriangles:s}=n,r=Mn.getPrimitive(),o=this.geometry.index,c=this.geometry.attributes.position,l=this.indirect?x=>{let v=this.resolveTriangleIndex(x);Me(r,v*3,o,c)}:x=>{Me(r,x*3,o,c)},h=Mn.getPrimitive(),u=t.geometry.index,d=t.geometry.attributes.position,f=t.indirect?x=>{let v=t.resolveTriangleIndex(x);Me(h,v*3,u,d)}:x=>{Me(h,x*3,u,d)};if(s){if(!(t instanceof i))throw new Error('MeshBVH: "intersectsTriangles" callback can only be used with another MeshBVH.');let x=(v,m,g,y,w,p,_,S)=>{for(let b=g,M=g+y;b<M;b++){f(b),h.a.applyMatrix4(e),h.b.applyMatrix4(e),h.c.applyMatrix4(e),h.needsUpdate=!0;for(let E=v,A=v+m;E<A;E++)if(l(E),r.needsUpdate=!0,s(r,h,E,b,w,p,_,S))return!0}return!1};if(a){let v=a;a=function(m,g,y,w,p,_,S,b){return v(m,g,y,w,p,_,S,b)?!0:x(m,g,y,w,p,_,S,b)}}else a=x}return super.bvhcast(t,e,{intersectsRanges:a})}intersectsBox(t,e){return Hl.set(t.min,t.max,e),Hl.needsUpdate=!0,this.shapecast({intersectsBounds:n=>Hl.intersectsBox(n),intersectsTriangle:n=>Hl.intersectsTriangle(n)})}intersectsSphere(t){return this.shapecast({intersectsBounds:e=>t.intersectsBox(e),intersectsTriangle:e=>e.intersectsSphere(t)})}closestPointToGeometry(t,e,n={},a={},s=0,r=1/0){return(this.indirect?eg:Jm)(this,t,e,n,a,s,r)}closestPointToPoint(t,e={},n=0,a=1/0){return Pm(this,t,e,n,a)}};var ks=(function(){var i="b9H79Tebbbe;veC9Geueu9Geub9Gbb9Gsuuuuuuuuuuuu99uueu9Gvuuuuub9Gruuuuuuub9Gouuuuuue999Gvuuuuueu9Gzuuuuuuuuuuu99uuuub9Gquuuuuuu99uueu9GPuuuuuuuuuuu99uueu9Gquuuuuuuu99ueu9Gruuuuuu99eu9Gwuuuuuu99ueu9Giuuue999GDuuuuuuuuueu9Gkuuuuuuuu99uub9Gluuuueu9Gluuuub9Giuuueui3EdilvorlwDiqkrxmPszdHObAAbeAlve9Weiiviebeoweuecj:Gdkr:Sdmo9TW9T9VV95dbH9F9F939H79T9F9J9H229F9Jt9VV7bbz9TW79O9V9Wt9F79P9T9W29P9M95bw8E9TW79O9V9Wt9F79P9T9W29P9M959x9Pt9OcttV9P9I91tW7bD8A9TW79O9V9Wt9F79P9T9W29P9M959x9Pt9O9v9W9K9HtWbqQ9TW79O9V9Wt9F79P9T9W29P9M959t29V9W9W95bkX9TW79O9V9Wt9F79P9T9W29P9M959qV919UWbmQ9TW79O9V9Wt9F79P9T9W29P9M959q9V9P9Ut7bPX9TW79O9V9Wt9F79P9T9W29P9M959t9J9H2WbsP9TW79O9V9Wt9FVW9TW79Obza9TW79O9V9Wt9F9V9Wt9P9T9P96W9wWVtW94SWt9J9O9sW9T9H9WbA59TW79O9V9Wt9F9NW9UWV9HtW9q9V79Pt9P9V9U9sW9T9H9WbCl79IV9RbXDwebcekdKYq:p:1dElbzOk:Q:tekYue99iuQ99eui99Due99xue9:w998Jjjjjbcj;sb9Rgs8Kjjjjbcbhzasc:Cefcbc;Kbz:xjjjb8AdnabaeSmbabaeadcdtz:wjjjb8AkdnamcdGTmbalcrfci4cbyd;y:L:cjbHjjjjbbhHasc:Cefasyd;8egecdtfaHBdbasaecefBd;8ecbhlcbhednadTmbabheadhOinaHaeydbci4fcb86bbaeclfheaOcufgOmbkcbhlabheadhOinaHaeydbgAci4fgCaCRbbgCceaAcrGgAtV86bbaCcu7aA4ceGalfhlaeclfheaOcufgOmbkcualcdtalcFFFFi0Ehekaecbyd;y:L:cjbHjjjjbbhzasc:Cefasyd;8egecdtfazBdbasaecefBd;8ealcd4alfhOcehHinaHgecethHaeaO6mbkcbhXcuaecdtgOaecFFFFi0Ecbyd;y:L:cjbHjjjjbbhHasc:Cefasyd;8egAcdtfaHBdbasaAcefBd;8eaHcFeaOz:xjjjbhQdnadTmbaecufhLcbhKindndnaQabaKcdtfgYydbgAc:v;t;h;Ev2aLGgOcdtfgCydbgHcuSmbceheinazaHcdtfydbaASmdaOaefhHaecefheaQaHaLGgOcdtfgCydbgHcu9hmbkkazaXcdtfaABdbaCaXBdbaXhHaXcefhXkaYaHBdbaKcefgKad9hmbkkaQcbyd;C:L:cjbH:bjjjbbasasyd;8ecufBd;8ekcbh8AcualcefgecdtaecFFFFi0Ecbyd;y:L:cjbHjjjjbbhKasc:Cefasyd;8egecdtfaKBdbasaKBdNeasaecefBd;8ecuadcitadcFFFFe0Ecbyd;y:L:cjbHjjjjbbhEasc:Cefasyd;8egecdtfaEBdbasaEBd:yeasaecefBd;8eascNefabadalcbz:cjjjbcualcdtgealcFFFFi0Eg3cbyd;y:L:cjbHjjjjbbhHasc:Cefasyd;8egOcdtfaHBdbasaOcefBd;8ea3cbyd;y:L:cjbHjjjjbbhXasc:Cefasyd;8egOcdtfaXBdbasaOcefBd;8eaHaXaialavazasc:Cefz:djjjbalcbyd;y:L:cjbHjjjjbbh5asc:Cefasyd;8egOcdtfa5BdbasaOcefBd;8ea3cbyd;y:L:cjbHjjjjbbhOasc:Cefasyd;8egAcdtfaOBdbasaAcefBd;8ea3cbyd;y:L:cjbHjjjjbbhAasc:Cefasyd;8egCcdtfaABdbasaCcefBd;8eaOcFeaez:xjjjbh8EaAcFeaez:xjjjbh8FdnalTmbindnaKa8AgAcefg8AcdtfydbgCaKaAcdtgefydbgOSmbaCaO9RhYaEaOcitfhaa8Faefhha8EaefhLcbhCindndnaaaCcitfydbgQaA9hmbaLaABdbahaABdbxekdnaKaQcdtggfgeclfydbgOaeydbgeSmbaOae9RhOaEaecitfheinaeydbaASmdaecwfheaOcufgOmbkka8FagfgeaAaQaeydbcuSEBdbaLaQaAaLydbcuSEBdbkaCcefgCaY9hmbkka8Aal9hmbkaHhOaXhAa8EhQa8FhCcbheindndnaeaOydbgL9hmbdnaeaAydbgL9hmbaQydbhLdnaCydbgYcu9hmbaLcu9hmba5aefcb86bbxikdnaYcuSmbaLcuSmbaeaYSmbaHaYcdtfydbaHaLcdtfydb9hmba5aefcd86bbxika5aefhadnaeaYSmbaeaLSmbaace86bbxikaacv86bbxdkdnaeaXaLcdtgYfydb9hmbdnaCydbgacuSmbaeaaSmbaQydbggcuSmbaeagSmba8FaYfydbghcuSmbahaLSmba8EaYfydbgYcuSmbaYaLSmbaHaacdtfydbgLaHaYcdtfydb9hmbaLaHagcdtfydbgYSmbaYaHahcdtfydb9hmba5aefcd86bbxika5aefcv86bbxdka5aefcv86bbxeka5aefa5aLfRbb86bbkaOclfhOaAclfhAaQclfhQaCclfhCalaecefge9hmbkdnamcaGTmbcbh8Jindndna5a8Jfg8KRbbg8Lc9:fPlbeebekdndndnaHa8Jcdtfydbgea8J9hmbcbhYcbh8MaqTmednazTmbcbh8Ma8JheinaqazaecdtgefydbfRbbce4a8MVceGh8MaXaefydbgea8J9hmbxikkcbh8Ma8JheinaqaefRbbce4a8MVceGh8MaXaecdtfydbgea8J9hmbxdkka5aefRbbhexeka8JheindnaKaecdtg8AfgeclfydbgOaeydbgeSmbaOae9RhgaEaecitfhhaHa8AfhacbhLinahaLcitfydbgQhednindnaKaecdtgCfgeclfydbgOaeydbgeSmbaOae9RhOaEaecitfheaaydbhAdninaHaeydbcdtfydbaASmeaecwfheaOcufgOTmdxbkkcbhexdkaXaCfydbgeaQ9hmbkcehekaYaeVhYaLcefgLag9hmbkkaXa8Afydbgea8J9hmbka8LclciaYceGEa8MEheka8Kae86bbka8Jcefg8Jal9hmbkkdnaqTmbdndnazTmbazheaHhOalhAindnaqaeydbfRbbceGTmba5aOydbfcv86bbkaeclfheaOclfhOaAcufgAmbxdkkaqheaHhOalhAindnaeRbbceGTmba5aOydbfcv86bbkaecefheaOclfhOaAcufgAmbkkaHhealhAa5hOindna5aeydbfRbbcv9hmbaOcv86bbkaeclfheaOcefhOaAcufgAmbkkamceGTmba5healhOindndnaeRbbcufPlbeebekaecv86bbkaecefheaOcufgOmbkkcbh8Ncualcx2alc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbh8Kasc:Cefasyd;8egecdtfa8KBdbasaecefBd;8eascbBd:qeas9cb83i1ea8Kaialavazasc1efz:ejjjbhydndnaDmbcbh8PcbhaxekcbhaawhecbhOindnaeIdbJbbbb9ETmbasaacdtfaOBdbaacefhakaeclfheaDaOcefgO9hmbkcuaaal2gecdtaecFFFFi0Ecbyd;y:L:cjbHjjjjbbh8Pasc:Cefasyd;8egecdtfa8PBdbasaecefBd;8ealTmbdnaambcbhaxekarcd4hgdnazTmbaacdthhcbhLa8PhYinaoazaLcdtfydbag2cdtfhQasheaYhOaahAinaOaQaeydbcdtgCfIdbawaCfIdbNUdbaeclfheaOclfhOaAcufgAmbkaYahfhYaLcefgLal9hmbxdkkaacdthhcbhLa8PhYinaoaLag2cdtfhQasheaYhOaahAinaOaQaeydbcdtgCfIdbawaCfIdbNUdbaeclfheaOclfhOaAcufgAmbkaYahfhYaLcefgLal9hmbkkcualc8S2gOalc;D;O;f8U0EgCcbyd;y:L:cjbHjjjjbbheasc:Cefasyd;8egAcdtfaeBdbasaAcefBd;8eaecbaOz:xjjjbhIcbh8RcbhgdnaaTmbcbh8NaCcbyd;y:L:cjbHjjjjbbhgasc:Cefasyd;8egecdtfagBdbasaecefBd;8eagcbaOz:xjjjb8Acuaaal2gecltgOaecFFFFb0Ecbyd;y:L:cjbHjjjjbbh8Rasc:Cefasyd;8egecdtfa8RBdbasaecefBd;8ea8RcbaOz:xjjjb8AamcjjjjdGTmbcualcltgealcFFFFb0Ecbyd;y:L:cjbHjjjjbbh8Nasc:Cefasyd;8egOcdtfa8NBdbasaOcefBd;8ea8Ncbaez:xjjjb8AkdnadTmbcbhQabhOina8KaOclfydbgLcx2fgeIdba8KaOydbgYcx2fgAIdbg8S:tgRa8KaOcwfydbghcx2fgCIdlaAIdlg8U:tg8VNaeIdla8U:tg8WaCIdba8S:tg8XN:tg8Ya8YNa8WaCIdwaAIdwg8Z:tg80NaeIdwa8Z:tg8Wa8VN:tg81a81Na8Wa8XNaRa80N:tg80a80NMMg8V:rhBa8Yh8Xa80h8Wa81hRdna8VJbbbb9EgATmba8YaB:vh8Xa80aB:vh8Wa81aB:vhRkaIaHaYcdtfydbgCc8S2fgeaRaB:rg8VaRNNg83aeIdbMUdbaea8Wa8Va8WNgUNg85aeIdlMUdlaea8Xa8Va8XNg86Ng87aeIdwMUdwaeaRaUNgUaeIdxMUdxaea86aRNg88aeIdzMUdzaea8Wa86Ng89aeIdCMUdCaeaRa8Va8Xa8ZNaRa8SNa8Ua8WNMM:mg8:Ng86NgRaeIdKMUdKaea8Wa86Ng8WaeId3MUd3aea8Xa86Ng8XaeIdaMUdaaea86a8:Ng86aeId8KMUd8Kaea8VaeIdyMUdyaIaHaLcdtfydbgLc8S2fgea83aeIdbMUdbaea85aeIdlMUdlaea87aeIdwMUdwaeaUaeIdxMUdxaea88aeIdzMUdzaea89aeIdCMUdCaeaRaeIdKMUdKaea8WaeId3MUd3aea8XaeIdaMUdaaea86aeId8KMUd8Kaea8VaeIdyMUdyaIaHahcdtfydbgYc8S2fgea83aeIdbMUdbaea85aeIdlMUdlaea87aeIdwMUdwaeaUaeIdxMUdxaea88aeIdzMUdzaea89aeIdCMUdCaeaRaeIdKMUdKaea8WaeId3MUd3aea8XaeIdaMUdaaea86aeId8KMUd8Kaea8VaeIdyMUdydna8NTmbdnaATmba8YaB:vh8Ya80aB:vh80a81aB:vh81ka8NaCcltfgeaBJbbbZNgRa80Ng8VaeIdlMUdlaeaRa8YNg8WaeIdwMUdwaeaRa81Ng8XaeIdbMUdbaeaRa8S:ma81Na8Ua80N:ta8Za8YN:tNgRaeIdxMUdxa8NaLcltfgea8VaeIdlMUdlaea8WaeIdwMUdwaea8XaeIdbMUdbaeaRaeIdxMUdxa8NaYcltfgea8VaeIdlMUdlaea8WaeIdwMUdwaea8XaeIdbMUdbaeaRaeIdxMUdxkaOcxfhOaQcifgQad6mbkkdnalTmbJq;x8J88J;n;m;m89J:v:;;w8ZamczGEamc;abGEh80cbhOaHhCazhQaIhea8KhAindnaOaCydb9hmbaOhLdnazTmbaQydbhLka80hRdnaqTmbJbbjZa80aqaLfRbbclGEhRkaecxfgLaLIdbJbbbbMUdbaeczfgLaLIdbJbbbbMUdbaecCfgLaLIdbJbbbbMUdbaeaRaecyfgLIdbg8YNgRaeIdbMUdbaeclfgYaRaYIdbMUdbaecwfgYaRaYIdbMUdbaecKfgYaYIdbaAIdbg8WaRN:tUdbaAcwfIdbh8Vaec3fgYaYIdbaRaAclfIdbg8XN:tUdbaecafgYaYIdbaRa8VN:tUdbaec8KfgYIdbh81aLa8YaRMUdbaYa81aRa8Va8VNa8Wa8WNa8Xa8XNMMNMUdbkaCclfhCaQclfhQaec8SfheaAcxfhAalaOcefgO9hmbkkdnadTmbcbh8AabhLinaba8AcdtfhYcbheindna5aLaefydbgCfRbbgOTmba5aYaec:G:G:cjbfydbcdtfydbgQfRbbcFeGgATmbdnaOclSghmbaOci6mbaAclSmbaAcd0mekdnaOcd0mba8EaCcdtfydbaQ9hmekdnaAcd0mba8FaQcdtfydbaC9hmekdndnahmbaAcl9hmekaOciSmeaAciSmekJbbbZJbbbZJbbacaAcdSEaOcdSEhUdna8KaYaec:K:G:cjbfydbcdtfydbcx2fgOIdwa8KaCcx2fgAIdwg86:tg8Sa8KaQcx2fghIdwa86:tg8Xa8XNahIdbaAIdbg8U:tg80a80NahIdlaAIdlg8Z:tg8Va8VNMMg81Na8Xa8Sa8XNaOIdba8U:tg83a80Na8VaOIdla8Z:tg85NMMg8WN:tg8Ya8YNa83a81Na80a8WN:tgRaRNa85a81Na8Va8WN:tg8Wa8WNMMgBJbbbb9ETmba8YaB:rgB:vh8Ya8WaB:vh8WaRaB:vhRkaUa81:rNgBa8Ya86NaRa8UNa8Za8WNMM:mg81Ng87a81Nh88a80a85Na8Va83N:tg81a81Na8Va8SNa8Xa85N:tg8Va8VNa8Xa83Na80a8SN:tg8Xa8XNMMg83:rh80a8Ya87Nh85a8Wa87Nh89aRa87Nh87a8WaBa8YNg8SNh8:a8SaRNhZaRaBa8WNgnNhca8Ya8SNh8Ya8WanNh8WaRaBaRNNh8Sdna83Jbbbb9ETmba81a80:vh81a8Xa80:vh8Xa8Va80:vh8VkaIaHaCcdtfydbc8S2fgOaOIdba8Sa8VaUa80:rNgRa8VNNMg80MUdbaOa8Wa8XaRa8XNg8SNMg83aOIdlMUdlaOa8Ya81aRa81Ng8WNMg8YaOIdwMUdwaOaca8Va8SNMg8SaOIdxMUdxaOaZa8Wa8VNMgUaOIdzMUdzaOa8:a8Xa8WNMg8WaOIdCMUdCaOa87a8VaRa81a86Na8Va8UNa8Za8XNMMg86:mNgRNMg8VaOIdKMUdKaOa89a8XaRNMg8XaOId3MUd3aOa85a81aRNMg81aOIdaMUdaaOa88a86aRN:tgRaOId8KMUd8KaOaBaOIdyMUdyaIaHaQcdtfydbc8S2fgOa80aOIdbMUdbaOa83aOIdlMUdlaOa8YaOIdwMUdwaOa8SaOIdxMUdxaOaUaOIdzMUdzaOa8WaOIdCMUdCaOa8VaOIdKMUdKaOa8XaOId3MUd3aOa81aOIdaMUdaaOaRaOId8KMUd8KaOaBaOIdyMUdykaeclfgecx9hmbkaLcxfhLa8Acifg8Aad6mbkkdnamcjeGTmbalTmbcbh9cindnaKa9cgecdtgOfydbghaKaecefg9ccdtfydbg8M9pmba8Kaecx2fhDaIaHaOfydbgCc8S2fh8AindnaHaEahcitfgeydbgLcdtfydbg8JaC0mbaeydlh8LcuhAaLheindnaKaecdtgYfgeclfydbgOaeydbgeSmbaOae9RhOaEaecitfheindnaHaeydbcdtfydbaC9hmbaAcu9hhQaLhAaQmbaeclfydbhAkaecwfheaOcufgOmbkkaXaYfydbgeaL9hmbkaAaLSmbaAcuSmba8KaLcx2fgeIdbaDIdbg81:tgRa8Ka8Lcx2fgOIdlaDIdlg80:tg8XNaeIdla80:tg8VaOIdba81:tg8YN:tg86a8KaAcx2fgAIdba81:tg8Za8VNaAIdla80:tg83aRN:tg8SNa8VaOIdwaDIdwgB:tg8UNaeIdwaB:tg8Wa8XN:tg85a83a8WNaAIdwaB:tg87a8VN:tgUNa8Wa8YNaRa8UN:tg88a87aRNa8Za8WN:tg89NMMa86a86Na85a85Na88a88NMM:rJ:A:z9z:;Na8Sa8SNaUaUNa89a89NMM:rN9Gmbdna8Ua8Wa8WNaRaRNa8Va8VNMMg8SNa8Wa8Ua8WNa8YaRNa8Va8XNMMg86N:tg8Ua8UNa8Ya8SNaRa86N:tg8Ya8YNa8Xa8SNa8Va86N:tg86a86NMMg8XJbbbb9ETmba8Ua8X:rg8X:vh8Ua86a8X:vh86a8Ya8X:vh8Yka8S:rg8Xa8UaBNa8Ya81Na80a86NMM:mgUNg85aUNhUa8Ua85Nh88a86a85Nh89a8Ya85Nh8:a86a8Xa8UNg85NhZa85a8YNhna8Ya8Xa86NgcNhJa8Ua85Nh8Ua86acNh86a8Ya8Xa8YNNh85dna87a8SNa8Wa87a8WNa8ZaRNa8Va83NMMg8YN:tg8Wa8WNa8Za8SNaRa8YN:tgRaRNa83a8SNa8Va8YN:tg8Va8VNMMg8YJbbbb9ETmba8Wa8Y:rg8Y:vh8Wa8Va8Y:vh8VaRa8Y:vhRka8Aa8AIdba85aRa8XaRNNMg8SMUdba8Aa86a8Va8Xa8VNg8ZNMg86a8AIdlMUdla8Aa8Ua8Wa8Xa8WNg8YNMg8Ua8AIdwMUdwa8AaJaRa8ZNMg8Za8AIdxMUdxa8Aana8YaRNMg83a8AIdzMUdza8AaZa8Va8YNMg85a8AIdCMUdCa8Aa8:aRa8Xa8WaBNaRa81Na80a8VNMMg81:mNg8YNMgRa8AIdKMUdKa8Aa89a8Va8YNMg8Va8AId3MUd3a8Aa88a8Wa8YNMg8Wa8AIdaMUdaa8AaUa81a8YN:tg8Ya8AId8KMUd8Ka8Aa8Xa8XMg8Xa8AIdyMUdyaIa8Jc8S2fgea8SaeIdbMUdbaea86aeIdlMUdlaea8UaeIdwMUdwaea8ZaeIdxMUdxaea83aeIdzMUdzaea85aeIdCMUdCaeaRaeIdKMUdKaea8VaeId3MUd3aea8WaeIdaMUdaaea8YaeId8KMUd8Kaea8XaeIdyMUdykahcefgha8M9hmbkka9cal9hmbkkdnadTmbaaTmbcbhYinJbbbbh80a8KabaYcdtfgeclfydbgLcx2fgOIdwa8Kaeydbghcx2fgAIdwg8Z:tg8Va8VNaOIdbaAIdbg83:tg8Wa8WNaOIdlaAIdlg85:tg8Xa8XNMMg8Sa8Kaecwfydbg8Acx2fgeIdwa8Z:tg8YNa8Va8YNa8WaeIdba83:tg81Na8XaeIdla85:tgBNMMgRa8VN:tJbbbbJbbjZa8Sa8Ya8YNa81a81NaBaBNMMg8UNaRaRN:tg86:va86Jbbbb9BEg86Nh88a8Ua8VNaRa8YN:ta86Nh89a8SaBNaRa8XN:ta86Nh8:a8Ua8XNaRaBN:ta86NhZa8Sa81NaRa8WN:ta86Nhna8Ua8WNaRa81N:ta86Nhca8WaBNa8Xa81N:tgRaRNa8Xa8YNa8VaBN:tgRaRNa8Va81Na8Wa8YN:tgRaRNMM:rJbbbZNhRa8Pahaa2g8JcdtfhOa8Pa8Aaa2g8McdtfhAa8PaLaa2gDcdtfhCa8Z:mhJa85:mh9ea83:mhTascjdfheaahQJbbbbhBJbbbbh86Jbbbbh8SJbbbbh8UJbbbbh8ZJbbbbh83Jbbbbh85Jbbbbh87JbbbbhUinaecwfaRa89aCIdbaOIdbg8Y:tg8XNa88aAIdba8Y:tg81NMg8VNUdbaeclfaRaZa8XNa8:a81NMg8WNUdbaeaRaca8XNana81NMg8XNUdbaecxfaRaJa8VNa9ea8WNa8YaTa8XNMMMg8YNUdbaRa8Va8WNNa8ZMh8ZaRa8Va8XNNa8UMh8UaRa8Wa8XNNa8SMh8SaRa8Ya8YNNaUMhUaRa8Va8YNNa87Mh87aRa8Wa8YNNa85Mh85aRa8Xa8YNNa83Mh83aRa8Va8VNNa86Mh86aRa8Wa8WNNaBMhBaRa8Xa8XNNa80Mh80aOclfhOaCclfhCaAclfhAaeczfheaQcufgQmbkagahc8S2fgea80aeIdbMUdbaeaBaeIdlMUdlaea86aeIdwMUdwaea8SaeIdxMUdxaea8UaeIdzMUdzaea8ZaeIdCMUdCaea83aeIdKMUdKaea85aeId3MUd3aea87aeIdaMUdaaeaUaeId8KMUd8KaeaRaeIdyMUdyagaLc8S2fgea80aeIdbMUdbaeaBaeIdlMUdlaea86aeIdwMUdwaea8SaeIdxMUdxaea8UaeIdzMUdzaea8ZaeIdCMUdCaea83aeIdKMUdKaea85aeId3MUd3aea87aeIdaMUdaaeaUaeId8KMUd8KaeaRaeIdyMUdyaga8Ac8S2fgea80aeIdbMUdbaeaBaeIdlMUdlaea86aeIdwMUdwaea8SaeIdxMUdxaea8UaeIdzMUdzaea8ZaeIdCMUdCaea83aeIdKMUdKaea85aeId3MUd3aea87aeIdaMUdaaeaUaeId8KMUd8KaeaRaeIdyMUdya8Ra8JcltfhLcbhOaahCinaLaOfgeascjdfaOfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbka8RaDcltfhLcbhOaahCinaLaOfgeascjdfaOfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbka8Ra8McltfhLcbhOaahCinaLaOfgeascjdfaOfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbkaYcifgYad6mbkkcbhAdndnamcwGgSmbJbbbbh86cbh9hcbh9icbh6xekcbh9ha3cbyd;y:L:cjbHjjjjbbh6asc:Cefasyd;8egecdtfa6BdbasaecefBd;8ecua6alabadaHz:fjjjbgCcltaCcjjjjiGEcbyd;y:L:cjbHjjjjbbh9iasc:Cefasyd;8egecdtfa9iBdbasaecefBd;8ea9iaCa6a8Kalz:gjjjbJFFuuh86aCTmba9iheaChOinaeIdbgRa86a86aR9EEh86aeclfheaOcufgOmbkaCh9hkdnalTmbaKclfheaKydbhCa5hOalhQcbhAincbaeydbgLaC9RaORbbcpeGEaAfhAaOcefhOaeclfheaLhCaQcufgQmbkaAce4hAkcuadaA9Rcifg9kcx2a9kc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbh0asc:Cefasyd;8egecdtfa0BdbasaecefBd;8ecua9kcdta9kcFFFFi0Ecbyd;y:L:cjbHjjjjbbh9masc:Cefasyd;8egecdtfa9mBdbasaecefBd;8ea3cbyd;y:L:cjbHjjjjbbh9nasc:Cefasyd;8egecdtfa9nBdbasaecefBd;8ealcbyd;y:L:cjbHjjjjbbh9oasc:Cefasyd;8egecdtfa9oBdbasaecefBd;8eaxaxNayJbbjZamclGEg9pa9pN:vh87JbbbbhUdnadak9nmbdna9kci6mbamcjdGh9qaaclth9ra0cwfh9sJbbbbh85JbbbbhUinascNefabadalaHz:cjjjbabh8Acbh3cbh9tinaba9tcdtfh8McbheindnaHa8AaefydbgAcdtghfydbgCaHa8Maec:W:G:cjbfydbcdtfydbgOcdtg8JfydbgQSmba5aOfRbbgYco2a5aAfRbbgLfRb;a:G:cjbg8LaLco2aYfgDRb;a:G:cjbg9cVcFeGTmbdnaQaC9nmbaDRb;W:G:cjbcFeGmekdnaLcufcFeGce0mbaYTmba8EahfydbaO9hmekdnaLTmbaYcufcFeGce0mba8Fa8JfydbaA9hmeka0a3cx2fgCaOaAa9ccFeGgQEBdlaCaAaOaQEBdbaCaQa8LGcb9hBdwa3cefh3kaeclfgecx9hmbkdna9tcifg9tad9pmba8Acxfh8Aa3cifa9k9nmekka3TmdcbhDinaIaHa0aDcx2fghydbgLcdtgCfydbg8Jc8S2fgeIdwa8KahydlgYcx2fgOIdwg8WNaeIdzaOIdbg8XNaeIdaMgRaRMMa8WNaeIdlaOIdlg8YNaeIdCa8WNaeId3MgRaRMMa8YNaeIdba8XNaeIdxa8YNaeIdKMgRaRMMa8XNaeId8KMMM:lhRJbbbbJbbjZaeIdyg8V:va8VJbbbb9BEh8Vdndnahydwg8MmbJFFuuhBxekJbbbbJbbjZaIaHaYcdtfydbc8S2fgeIdyg81:va81Jbbbb9BEaeIdwa8KaLcx2fgOIdwg81NaeIdzaOIdbg80NaeIdaMgBaBMMa81NaeIdlaOIdlgBNaeIdCa81NaeId3Mg81a81MMaBNaeIdba80NaeIdxaBNaeIdKMg81a81MMa80NaeId8KMMM:lNhBka8VaRNh80dnaaTmbagaLc8S2fgAIdwa8WNaAIdza8XNaAIdaMgRaRMMa8WNaAIdla8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8PaYaa2gQcdtfhOa8RaLaa2g8AcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEh8Sdndna8MmbJbbbbhRxekagaYc8S2fgAIdwa8KaLcx2fgeIdwg8WNaAIdzaeIdbg8XNaAIdaMgRaRMMa8WNaAIdlaeIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Pa8AcdtfhOa8RaQcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEhRka80a8SMh80aBaRMhBdndndna5aLfRbbc9:fPibeedkdna8Fa8Ea8EaCfydbaYSEaXaCfydbgQcdtfydbgCcu9hmbaXaYcdtfydbhCkagaQc8S2fgAIdwa8KaCcx2fgeIdwg8WNaAIdzaeIdbg8XNaAIdaMgRaRMMa8WNaAIdlaeIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8PaCaa2g8AcdtfhOa8RaQaa2g8JcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEh8Sdndna8MmbJbbbbhRxekagaCc8S2fgAIdwa8KaQcx2fgeIdwg8WNaAIdzaeIdbg8XNaAIdaMgRaRMMa8WNaAIdlaeIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Pa8JcdtfhOa8Ra8AcltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaR:lgRa81aRa819DEaRa9qEhRka80a8SMh80aBaRMhBxdkaXaCfydbgCaLSmbaHaYcdtfydbh8Aindndna8EaCcdtgQfydbgecuSmbaHaecdtfydba8ASmekdna8FaQfydbgecuSmbaHaecdtfydba8ASmekaYhekagaCc8S2fgAIdwa8Kaecx2fgOIdwg8WNaAIdzaOIdbg8XNaAIdaMgRaRMMa8WNaAIdlaOIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Paeaa2cdtfhOa8RaCaa2cltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbka80aR:lgRa81aRa819DEaRa9qEMh80aXaQfydbgCaL9hmbkkdna5aYfRbbgeciSmbaecl9hmeka8MTmbaXaYcdtfydbgCaYSmbindndna8EaCcdtgQfydbgecuSmbaHaecdtfydba8JSmekdna8FaQfydbgecuSmbaHaecdtfydba8JSmekaLhekagaCc8S2fgAIdwa8Kaecx2fgOIdwg8WNaAIdzaOIdbg8XNaAIdaMgRaRMMa8WNaAIdlaOIdlg8YNaAIdCa8WNaAId3MgRaRMMa8YNaAIdba8XNaAIdxa8YNaAIdKMgRaRMMa8XNaAId8KMMMhRa8Paeaa2cdtfhOa8RaCaa2cltfheaAIdyh81aahAinaOIdbg8Va8Va81NaecxfIdba8WaecwfIdbNa8XaeIdbNa8YaeclfIdbNMMMg8Va8VM:tNaRMhRaOclfhOaeczfheaAcufgAmbkaBaR:lgRa81aRa819DEaRa9qEMhBaXaQfydbgCaY9hmbkkahaBa80aBa809DgeEUdwahaLaYaea8Mcb9hGgeEBdlahaYaLaeEBdbaDcefgDa39hmbkascjdfcbcj;qbz:xjjjb8Aa9shea3hOinascjdfaeydbcA4cF8FGgAcFAaAcFA6EcdtfgAaAydbcefBdbaecxfheaOcufgOmbkcbhecbhOinascjdfaefgAydbhCaAaOBdbaCaOfhOaeclfgecj;qb9hmbkcbhea9shOinascjdfaOydbcA4cF8FGgAcFAaAcFA6EcdtfgAaAydbgAcefBdba9maAcdtfaeBdbaOcxfhOa3aecefge9hmbkadak9RgAci9Uh9udnalTmbcbhea9nhOinaOaeBdbaOclfhOalaecefge9hmbkkcbh9va9ocbalz:xjjjbh9caAcO9Uh9wa9uce4h9tcbh8Lcbh8Mdnina0a9ma8Mcdtfydbcx2fg8JIdwgRa879Emea8La9u9pmeJFFuuh8Vdna9ta39pmba0a9ma9tcdtfydbcx2fIdwJbb;aZNh8VkdnaRa8V9ETmbaRaU9ETmba8La9w0mdkdna9caHa8JydlgDcdtg9xfg8AydbgAfg9yRbba9caHa8Jydbghcdtg9zfydbgefg9ARbbVmba5ahfRbbh9BdndnaKaecdtfgOclfydbgCaOydbgOSmbaCaO9RhCa8KaAcx2fhLa8Kaecx2fhYaEaOcitfheindna9naeydbcdtfydbgOaASmba9naeclfydbcdtfydbgQaASmbaOaQSmba8KaQcx2fgQIdba8KaOcx2fgOIdbg8W:tgRaYIdlaOIdlg8X:tg80NaQIdla8X:tg8VaYIdba8W:tgBN:tg8YaRaLIdla8X:tg8SNa8VaLIdba8W:tg8UN:tg8XNa8VaYIdwaOIdwg81:tg8ZNaQIdwa81:tg8Wa80N:tg80a8VaLIdwa81:tg83Na8Wa8SN:tg8VNa8WaBNaRa8ZN:tg81a8Wa8UNaRa83N:tgRNMMa8Ya8YNa80a80Na81a81NMMa8Xa8XNa8Va8VNaRaRNMMN:rJbbj8:N9FmikaecwfheaCcufgCmbkkdndna9Bc99fcFeGce0mba9na9zfaDBdbaXa9zfydbgeahSmeina8AydbhAdndna8EaecdtgOfydbgecuSmbaHaecdtfydbaASmekdna8FaOfydbgecuSmbaHaecdtfydbaASmekaDheka9naOfaeBdbaXaOfydbgeah9hmbxdkkdndna9BcFeGcdSmbaDhexekdna8Fa8Ea8Ea9zfydbaDSEaXa9zfydbghcdtfydbgecu9hmbaXa9xfydbheka9na9zfaDBdbka9nahcdtfaeBdbka9Ace86bba9yce86bba8JIdwgRaUaUaR9DEhUa9vcefh9vcecda9BcFeGceSEa8Lfh8Lxeka9tcefh9tka8Mcefg8Ma39hmbkka9vTmddnalTmbcbhLcbhhindna9nahcdtgefydbgAahSmbaHaAcdtfydbh8AdnahaHaefydb9hg8JmbaIa8Ac8S2fgeaIahc8S2fgOIdbaeIdbMUdbaeaOIdlaeIdlMUdlaeaOIdwaeIdwMUdwaeaOIdxaeIdxMUdxaeaOIdzaeIdzMUdzaeaOIdCaeIdCMUdCaeaOIdKaeIdKMUdKaeaOId3aeId3MUd3aeaOIdaaeIdaMUdaaeaOId8KaeId8KMUd8KaeaOIdyaeIdyMUdya8NTmba8Na8Acltfgea8NahcltfgOIdbaeIdbMUdbaeaOIdlaeIdlMUdlaeaOIdwaeIdwMUdwaeaOIdxaeIdxMUdxkaaTmbagaAc8S2fgeagahc8S2g8MfgOIdbaeIdbMUdbaeaOIdlaeIdlMUdlaeaOIdwaeIdwMUdwaeaOIdxaeIdxMUdxaeaOIdzaeIdzMUdzaeaOIdCaeIdCMUdCaeaOIdKaeIdKMUdKaeaOId3aeId3MUd3aeaOIdaaeIdaMUdaaeaOId8KaeId8KMUd8KaeaOIdyaeIdyMUdya9raA2hYa8RhOaahCinaOaYfgeaOaLfgAIdbaeIdbMUdbaeclfgQaAclfIdbaQIdbMUdbaecwfgQaAcwfIdbaQIdbMUdbaecxfgeaAcxfIdbaeIdbMUdbaOczfhOaCcufgCmbka8JmbJbbbbJbbjZaIa8MfgeIdygR:vaRJbbbb9BEaeIdwa8Ka8Acx2fgOIdwgRNaeIdzaOIdbg8VNaeIdaMg8Wa8WMMaRNaeIdlaOIdlg8WNaeIdCaRNaeId3MgRaRMMa8WNaeIdba8VNaeIdxa8WNaeIdKMgRaRMMa8VNaeId8KMMM:lNgRa85a85aR9DEh85kaLa9rfhLahcefghal9hmbkcbhOa8EheindnaeydbgAcuSmbdnaOa9naAcdtgCfydbgA9hmbcuhAa8EaCfydbgCcuSmba9naCcdtfydbhAkaeaABdbkaeclfhealaOcefgO9hmbkcbhOa8FheindnaeydbgAcuSmbdnaOa9naAcdtgCfydbgA9hmbcuhAa8FaCfydbgCcuSmba9naCcdtfydbhAkaeaABdbkaeclfhealaOcefgO9hmbkka85aUaaEh85cbhOabhecbhAindnaHa9naeydbcdtfydbgLcdtfydbgCaHa9naeclfydbcdtfydbgYcdtfydbgQSmbaCaHa9naecwfydbcdtfydbg8AcdtfydbghSmbaQahSmbabaOcdtfgCaLBdbaCcwfa8ABdbaCclfaYBdbaOcifhOkaecxfheaAcifgAad6mbkdndnaSmbaOhdxekdnaOak0mbaOhdxekdna86a859FmbaOhdxekJFFuuh86cbhdabhecbhAindna9ia6aeydbgCcdtfydbcdtfIdbgRa859ETmbaeclf8Pdbh9CabadcdtfgQaCBdbaQclfa9C83dbaRa86a86aR9EEh86adcifhdkaecxfheaAcifgAaO6mbkkadak0mbxdkkascNefabadalaHz:cjjjbkdndnadak0mbadhYxekdnaSmbadhYxekdna86a879FmbadhYxekcehQina86Jbb;aZNgRa87aRa879DEh8WJbbbbhRdna9hTmba9ihea9hhOinaeIdbg8VaRa8Va8W9FEaRa8VaR9EEhRaeclfheaOcufgOmbkkJFFuuh86cbhYabhecbhOindna9ia6aeydbgAcdtfydbcdtfIdbg8Va8W9ETmbaeclf8Pdbh9CabaYcdtfgCaABdbaCclfa9C83dba8Va86a86a8V9EEh86aYcifhYkaecxfheaOcifgOad6mbkdnaQaYad9hVceGmbadhYxdkaRaUaUaR9DEhUaYak9nmecbhQaYhda86a879FmbkkdnamcjjjjdGTmba9ocbalz:xjjjbh8AdnaYTmbabheaYhOina8AaeydbgAfce86bba8AaHaAcdtfydbfce86bbaeclfheaOcufgOmbkkascNefabaYalaHz:cjjjbdndnalTmbcbhCindna8AaCfRbbTmbdna5aCfRbbPlbeebekdnaHaCcdtgLfydbgeaCSmba8KaCcx2fgOa8Kaecx2fgeydwBdwaOae8Pdb83dbxekaIaCc8S2fgQIdygnanJL:3;rUNgRMh87aQIdwgxaRMh8SaQIdlg9DaRMh8UaQIdbg9EaRMh81aQIdag9FaRa8KaCcx2fg8JIdwg88N:th8ZaQId3g9GaRa8JIdlg89N:th83aQIdKg9Ha8JIdbg8:aRN:th80JbbbbhZaQIdCg9IJbbbbMh85aQIdzg9JJbbbbMhBaQIdxg9KJbbbbMh86dndnaaTmbaChAinJbbbba87agaAc8S2fgOIdygR:vaRJbbbb9BEhRa8RaAaa2cltfheaOIdaa87Na8ZMh8ZaOId3a87Na83Mh83aOIdKa87Na80Mh80aOIdCa87Na85Mh85aOIdza87NaBMhBaOIdxa87Na86Mh86aOIdwa87Na8SMh8SaOIdla87Na8UMh8UaOIdba87Na81Mh81aahOina8ZaecwfIdbg8VaecxfIdbg8YNaRN:th8Za83aeclfIdbg8Wa8YNaRN:th83a85a8Wa8VNaRN:th85a81aeIdbg8Xa8XNaRN:th81a80a8Xa8YNaRN:th80aBa8Xa8VNaRN:thBa86a8Xa8WNaRN:th86a8Sa8Va8VNaRN:th8Sa8Ua8Wa8WNaRN:th8UaeczfheaOcufgOmbkaXaAcdtfydbgAaC9hmbka8NTmba8NaCcltfgeIdxhTaeIdwhcaeIdlhJaeIdbhRxekJbbbbhTJbbbbhcJbbbbhJJbbbbhRkaBa81:vg8Wa80Na8Z:ta85aBa86a81:vg8VN:tg8Za8Ua86a8VN:tg8Y:vg8Xa8Va80Na83:tg8UN:th83acaRa8WN:taJaRa8VN:tg86a8XN:tg85a8SaBa8WN:ta8Za8XN:tgB:vg8S:mh8Za86a8Y:vgc:mhJdnJbbbbaRaRa81:vg9eN:ta86acN:ta85a8SN:tg86:la87J:983:g81NgR9ETmba8Za83NaJa8UNa9ea80NaT:tMMa86:vhZka81:laR9ETmba8Y:laR9ETmbaB:laR9ETmba9e:maZNa8W:ma8ZaZNa83aB:vMgBNa8V:maJaZNa8X:maBNa8Ua8Y:vMMg85Na80:ma81:vMMMh87aKaLfgeclfydbgOaeydbge9RhhaEaecitfhLJbbbbhRdnaOaeSg8MmbJbbbbhRaLheahhAina8Kaeclfydbcx2fgOIdwa88:tg8Va8VNaOIdba8::tg8Va8VNaOIdla89:tg8Va8VNMMg8Va8Kaeydbcx2fgOIdwa88:tg8Wa8WNaOIdba8::tg8Wa8WNaOIdla89:tg8Wa8WNMMg8WaRaRa8W9DEgRaRa8V9DEhRaecwfheaAcufgAmbkaR:rgRaRNhRkaBa88:tg8Va8VNa87a8::tg8Va8VNa85a89:tg8Va8VNMMaR9EmbaQId8KhZdna8Mmbina8KaLclfydbcx2fgeIdba8KaLydbcx2fgOIdbg8W:tgRa89aOIdlg8X:tg80NaeIdla8X:tg8Va8:a8W:tg86N:tg8YaRa85a8X:tg8SNa8Va87a8W:tg8UN:tg8XNa8Va88aOIdwg81:tg8ZNaeIdwa81:tg8Wa80N:tg80a8VaBa81:tg83Na8Wa8SN:tg8VNa8Wa86NaRa8ZN:tg81a8Wa8UNaRa83N:tgRNMMa8Ya8YNa80a80Na81a81NMMa8Xa8XNa8Va8VNaRaRNMMN:rJbbj8:N9FmdaLcwfhLahcufghmbkkJbbbbJbbjZan:vanJbbbb9BEgRaxaBNa9Ja87Na9FMg8Va8VMMaBNa9Da85Na9IaBNa9GMg8Va8VMMa85Na9Ea87Na9Ka85Na9HMg8Va8VMMa87NaZMMM:lNaRaxa88Na9Ja8:Na9FMg8Va8VMMa88Na9Da89Na9Ia88Na9GMg8Va8VMMa89Na9Ea8:Na9Ka89Na9HMg8Va8VMMa8:NaZMMM:lNJbb;aZNJ:983:g81M9Emba8JaBUdwa8Ja85Udla8Ja87UdbkaCcefgCal9hmbkdnaambcbhaxdkcbhQindna8AaQfRbbTmbaHaQcdtgefydbaQ9hmba5aQfhhaXaefh8Ja8KaQcx2fhAa8PaQaa2cdtfh8McbhEincuhCdnahRbbc99fcFeGce0mbaQhCa8JydbgeaQSmba8PaEcdtgOfhLa8MaOfIdbhRaQhCinaChOcuhCdnaLaeaa2cdtfIdbaR9CmbaOcuSmbaOhCagaec8S2fIdyagaOc8S2fIdy9ETmbaehCkaXaecdtfydbgeaQ9hmbkka8PaEcdtfhLa8RaEcltfhKaQheinaLaeaa2cdtfJbbbbJbbjZagaeaCaCcuSEgOc8S2fIdygR:vaRJbbbb9BEaKaOaa2cltfgOIdwaAIdwNaOIdbaAIdbNaOIdlaAIdlNMMaOIdxMNUdbaXaecdtfydbgeaQ9hmbkaEcefgEaa9hmbkkaQcefgQal9hmbxdkkaambcbhakaiavaoarawaaala8Ka8Pazasayasc1efa5a8Aaqz:hjjjbkdnamcjjjjlGTmbazmbaYTmbabhecbhLina5aeydbgAfRbbc3thQaecwfgXydbhHcjjjj94hCdna8EaAcdtgEfydbaeclfgKydbgOSmbcjjjj94cba8FaOcdtfydbaASEhCkaeaQaCVaAVBdba5aOfRbbc3thacjjjj94hCcjjjj94hQdna8EaOcdtfydbaHSmbcjjjj94cba8FaHcdtfydbaOSEhQkaKaaaQVaOVBdba5aHfRbbc3thOdna8EaHcdtfydbaASmbcjjjj94cba8FaEfydbaHSEhCkaXaOaCVaHVBdbaecxfheaLcifgLaY6mbkkdnazTmbaYTmbaYheinabazabydbcdtfydbBdbabclfhbaecufgembkkdnaPTmbaPa9paU:rNUdbkdnasyd;8egHTmbaHcdtasc:Ceffc98fheinaeydbcbyd;C:L:cjbH:bjjjbbaec98fheaHcufgHmbkkascj;sbf8KjjjjbaYk;Yieouabydlhvabydbclfcbaicdtz:xjjjbhoadci9UhrdnadTmbdnalTmbaehwadhDinaoalawydbcdtfydbcdtfgqaqydbcefBdbawclfhwaDcufgDmbxdkkaehwadhDinaoawydbcdtfgqaqydbcefBdbawclfhwaDcufgDmbkkdnaiTmbcbhDaohwinawydbhqawaDBdbawclfhwaqaDfhDaicufgimbkkdnadci6mbinaecwfydbhwaeclfydbhDaeydbhidnalTmbalawcdtfydbhwalaDcdtfydbhDalaicdtfydbhikavaoaicdtfgqydbcitfaDBdbavaqydbcitfawBdlaqaqydbcefBdbavaoaDcdtfgqydbcitfawBdbavaqydbcitfaiBdlaqaqydbcefBdbavaoawcdtfgwydbcitfaiBdbavawydbcitfaDBdlawawydbcefBdbaecxfhearcufgrmbkkabydbcbBdbk:todDue99aicd4aifhrcehwinawgDcethwaDar6mbkcuaDcdtgraDcFFFFi0Ecbyd;y:L:cjbHjjjjbbhwaoaoyd9GgqcefBd9GaoaqcdtfawBdbawcFearz:xjjjbhkdnaiTmbalcd4hlaDcufhxcbhminamhDdnavTmbavamcdtfydbhDkcbadaDal2cdtfgDydlgwawcjjjj94SEgwcH4aw7c:F:b:DD2cbaDydbgwawcjjjj94SEgwcH4aw7c;D;O:B8J27cbaDydwgDaDcjjjj94SEgDcH4aD7c:3F;N8N27axGhwamcdthPdndndnavTmbakawcdtfgrydbgDcuSmeadavaPfydbal2cdtfgsIdbhzcehqinaqhrdnadavaDcdtfydbal2cdtfgqIdbaz9CmbaqIdlasIdl9CmbaqIdwasIdw9BmlkarcefhqakawarfaxGgwcdtfgrydbgDcu9hmbxdkkakawcdtfgrydbgDcuSmbadamal2cdtfgsIdbhzcehqinaqhrdnadaDal2cdtfgqIdbaz9CmbaqIdlasIdl9CmbaqIdwasIdw9BmikarcefhqakawarfaxGgwcdtfgrydbgDcu9hmbkkaramBdbamhDkabaPfaDBdbamcefgmai9hmbkkakcbyd;C:L:cjbH:bjjjbbaoaoyd9GcufBd9GdnaeTmbaiTmbcbhDaehwinawaDBdbawclfhwaiaDcefgD9hmbkcbhDaehwindnaDabydbgrSmbawaearcdtfgrydbBdbaraDBdbkabclfhbawclfhwaiaDcefgD9hmbkkk;:odvuv998Jjjjjbca9Rgocbyd1:G:cjbBdKaocb8Pdj:G:cjb83izaocbydN:G:cjbBdwaocb8Pd:m:G:cjb83ibdnadTmbaicd4hrdnabmbdnalTmbcbhwinaealawcdtfydbar2cdtfhDcbhiinaoczfaifgqaDaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkawcefgwad9hmbxikkarcdthwcbhDincbhiinaoczfaifgqaeaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkaeawfheaDcefgDad9hmbxdkkdnalTmbcbhwinabawcx2fgiaealawcdtfydbar2cdtfgDIdbUdbaiaDIdlUdlaiaDIdwUdwcbhiinaoczfaifgqaDaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkawcefgwad9hmbxdkkarcdthlcbhwaehDinabawcx2fgiaeawar2cdtfgqIdbUdbaiaqIdlUdlaiaqIdwUdwcbhiinaoczfaifgqaDaifIdbgkaqIdbgxaxak9EEUdbaoaifgqakaqIdbgxaxak9DEUdbaiclfgicx9hmbkaDalfhDawcefgwad9hmbkkJbbbbaoIdbaoIdzgx:tgkakJbbbb9DEgkaoIdlaoIdCgm:tgPaPak9DEgkaoIdwaoIdKgP:tgsasak9DEhsdnabTmbadTmbJbbbbJbbjZas:vasJbbbb9BEhkinabakabIdbax:tNUdbabclfgoakaoIdbam:tNUdbabcwfgoakaoIdbaP:tNUdbabcxfhbadcufgdmbkkdnavTmbavaPUdwavamUdlavaxUdbkask:WlewudnaeTmbcbhvabhoinaoavBdbaoclfhoaeavcefgv9hmbkkdnaiTmbcbhrinadarcdtfhwcbhDinalawaDcdtgvyd:G:G:cjbcdtfydbcdtfydbhodnalawavfydbcdtfydbgqabaqcdtfgkydbgvSmbinakabavgqcdtfgxydbgvBdbaxhkaqav9hmbkkdnaoabaocdtfgkydbgvSmbinakabavgocdtfgxydbgvBdbaxhkaoav9hmbkkdnaqaoSmbabaqaoaqao0Ecdtfaqaoaqao6EBdbkaDcefgDci9hmbkarcifgrai6mbkkdnaembcbskcbhxindnalaxcdtgvfydbax9hmbaxhodnaxabavfgDydbgvSmbaDhqinaqabavgocdtfgkydbgvBdbakhqaoav9hmbkkaDaoBdbkaxcefgxae9hmbkcbhkabhvcbhoindndnaoalydbgq9hmbdnaoavydbgq9hmbavakBdbakcefhkxdkavabaqcdtfydbBdbxekavabaqcdtfydbBdbkalclfhlavclfhvaeaocefgo9hmbkakk;jiilud99euabcbaecltz:xjjjbhvdnalTmbadhoaihralhwinarcwfIdbhDarclfIdbhqavaoydbcltfgkarIdbakIdbMUdbakaqakIdlMUdlakaDakIdwMUdwakakIdxJbbjZMUdxaoclfhoarcxfhrawcufgwmbkkdnaeTmbavhkaehrinakcxfgoIdbhDaocbBdbakakIdbJbbbbJbbjZaD:vaDJbbbb9BEgDNUdbakclfgoaDaoIdbNUdbakcwfgoaDaoIdbNUdbakczfhkarcufgrmbkkdnalTmbinavadydbcltfgkaicwfIdbakIdw:tgDaDNaiIdbakIdb:tgDaDNaiclfIdbakIdl:tgDaDNMMgDakIdxgqaqaD9DEUdxadclfhdaicxfhialcufglmbkkdnaeTmbavcxfhkinabakIdbUdbakczfhkabclfhbaecufgembkkk:moerudnaoTmbaecd4hzdnavTmbaicd4hHavcdthOcbhAindnaPaAfRbbTmbaAhednaDTmbaDaAcdtfydbhekdnasTmbasaefRbbceGmekdnamaAfRbbcvSmbabaeaz2cdtfgiaraAcx2fgCIdbakNaxIdbMUdbaiaCIdlakNaxIdlMUdlaiaCIdwakNaxIdwMUdwkadaeaH2cdtfhXaqheawhiavhCinaXaeydbcdtgQfaiIdbalaQfIdb:vUdbaeclfheaiclfhiaCcufgCmbkkawaOfhwaAcefgAao9hmbxdkkdnasmbcbheaDhiindnaPaefRbbTmbaehCdnaDTmbaiydbhCkamaefRbbcvSmbabaCaz2cdtfgCarIdbakNaxIdbMUdbaCarclfIdbakNaxIdlMUdlaCarcwfIdbakNaxIdwMUdwkaiclfhiarcxfhraoaecefge9hmbxdkkdnaDTmbindnaPRbbTmbasaDydbgefRbbceGmbamRbbcvSmbabaeaz2cdtfgearIdbakNaxIdbMUdbaearclfIdbakNaxIdlMUdlaearcwfIdbakNaxIdwMUdwkaPcefhPaDclfhDamcefhmarcxfhraocufgombxdkkazcdthicbheindnaPaefRbbTmbasaefRbbceGmbamaefRbbcvSmbabarIdbakNaxIdbMUdbabclfarclfIdbakNaxIdlMUdbabcwfarcwfIdbakNaxIdwMUdbkarcxfhrabaifhbaoaecefge9hmbkkk8MbabaeadaialavcbcbcbcbcbaoarawaDz:bjjjbk8MbabaeadaialavaoarawaDaqakaxamaPz:bjjjbkRbababaeadaialavaoarawaDaqakaxcjjjjdVamz:bjjjbk:vgoque99due99duq998Jjjjjbc;Wb9Rgq8Kjjjjbcbhkaqcxfcbc;Kbz:xjjjb8Aaqcualcx2alc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbgxBdxaqceBd2axaialavcbcbz:ejjjb8AaqcualcdtalcFFFFi0Egmcbyd;y:L:cjbHjjjjbbgiBdzaqcdBd2dndnJFF959eJbbjZawJbbjZawJbbjZ9DE:vawJ9VO:d869DEgw:lJbbb9p9DTmbaw:OhPxekcjjjj94hPkadci9Uhsarco9UhzdndnaombaPcd9imekdnalTmbaPcuf:YhwdnaoTmbcbhvaihHaxhOindndnaoavfRbbceGTmbavcjjjjlVhAxekdndnaOclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcqthAdndnaOcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXVhAdndnaOIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXcCtVhAkaHaABdbaHclfhHaOcxfhOalavcefgv9hmbxdkkaxhvaihOalhHindndnavIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcCthAdndnavclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcqtaAVhAdndnavcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaOaAaXVBdbavcxfhvaOclfhOaHcufgHmbkkadTmbcbhkaehvcbhOinakaiavclfydbcdtfydbgHaiavcwfydbcdtfydbgA9haiavydbcdtfydbgXaH9haXaA9hGGfhkavcxfhvaOcifgOad6mbkkarci9UhQdndnaz:Z:rJbbbZMgw:lJbbb9p9DTmbaw:Ohvxekcjjjj94hvkaQ:ZhLcbhKc:bwhzdninakaQ9pmeazaP9Rcd9imeavazcufgOavaO9iEaPcefavaP9kEhYdnalTmbaYcuf:YhwdnaoTmbcbhOaihHaxhvindndnaoaOfRbbceGTmbaOcjjjjlVhAxekdndnavclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcqthAdndnavcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXVhAdndnavIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaAaXcCtVhAkaHaABdbaHclfhHavcxfhvalaOcefgO9hmbxdkkaxhvaihOalhHindndnavIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhAxekcjjjj94hAkaAcCthAdndnavclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcqtaAVhAdndnavcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaOaAaXVBdbavcxfhvaOclfhOaHcufgHmbkkcbhOdnadTmbaehvcbhHinaOaiavclfydbcdtfydbgAaiavcwfydbcdtfydbgX9haiavydbcdtfydbgraA9haraX9hGGfhOavcxfhvaHcifgHad6mbkkdnas:ZgCaL:taY:Ygwaz:Y:tg8ANak:ZgEaO:Zg3:tNaEaL:tawaP:Y:tg5Na3aC:tNMg8EJbbbb9BmbaCaE:ta5a8Aa3aL:tNNNa8E:vawMhwkdndnaOaQ0mbaOhkaYhPxekaOhsaYhzkdndnaKcl0mbdnawJbbbZMgw:lJbbb9p9DTmbaw:Ohvxdkcjjjj94hvxekaPazfcd9ThvkaKcefgKcs9hmbkkdndndnakmbJbbjZhwcbhOcdhvaDmexdkalcd4alfhHcehOinaOgvcethOavaH6mbkaqcuavcdtavcFFFFi0Ecbyd;y:L:cjbHjjjjbbgYBdCaqciBd2aqamcbyd;y:L:cjbHjjjjbbgzBdKaqclBd2dnalTmbaPcuf:YhwdnaoTmbcbhOaihAaxhHindndnaoaOfRbbceGTmbaOcjjjjlVhXxekdndnaHclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcqthXdndnaHcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkaXarVhXdndnaHIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkaXarcCtVhXkaAaXBdbaAclfhAaHcxfhHalaOcefgO9hmbxdkkaxhOaihHalhAindndnaOIdbawNJbbbZMgC:lJbbb9p9DTmbaC:OhXxekcjjjj94hXkaXcCthXdndnaOclfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkarcqtaXVhXdndnaOcwfIdbawNJbbbZMgC:lJbbb9p9DTmbaC:Ohrxekcjjjj94hrkaHaXarVBdbaOcxfhOaHclfhHaAcufgAmbkkaqcuaYavazaialz:mjjjbgXc8S2gvaXc;D;O;f8U0Ecbyd;y:L:cjbHjjjjbbgiBd3aqcvBd2aicbavz:xjjjbhOdnadTmbcbhraehiinaxaiclfydbgocx2fgvIdbaxaiydbgPcx2fgHIdbg3:tgCaxaicwfydbgYcx2fgAIdlaHIdlg8A:tgwNavIdla8A:tgEaAIdba3:tg8EN:tgLaLNaEaAIdwaHIdwg5:tg8FNavIdwa5:tgEawN:tgwawNaEa8ENaCa8FN:tgCaCNMMg8E:rhEJbbnnJbbjZazaPcdtfydbgvazaocdtfydbgASavazaYcdtfydbgoSGgHEh8Fdna8EJbbbb9ETmbaLaE:vhLaCaE:vhCawaE:vhwkaOavc8S2fgvavIdbawa8FaE:rNgEawNNg8FMUdbavaCaEaCNgaNghavIdlMUdlavaLaEaLNg8ENggavIdwMUdwavawaaNgaavIdxMUdxava8EawNg8JavIdzMUdzavaCa8ENg8EavIdCMUdCavawaEaLa5Nawa3Na8AaCNMM:mg8ANg3NgwavIdKMUdKavaCa3NgCavId3MUd3avaLa3NgLavIdaMUdaava3a8ANg3avId8KMUd8KavaEavIdyMUdydnaHmbaOaAc8S2fgva8FavIdbMUdbavahavIdlMUdlavagavIdwMUdwavaaavIdxMUdxava8JavIdzMUdzava8EavIdCMUdCavawavIdKMUdKavaCavId3MUd3avaLavIdaMUdaava3avId8KMUd8KavaEavIdyMUdyaOaoc8S2fgva8FavIdbMUdbavahavIdlMUdlavagavIdwMUdwavaaavIdxMUdxava8JavIdzMUdzava8EavIdCMUdCavawavIdKMUdKavaCavId3MUd3avaLavIdaMUdaava3avId8KMUd8KavaEavIdyMUdykaicxfhiarcifgrad6mbkkcbhAaqcuaXcdtgvaXcFFFFi0Egicbyd;y:L:cjbHjjjjbbgHBdaaqcoBd2aqaicbyd;y:L:cjbHjjjjbbgiBd8KaqcrBd2aHcFeavz:xjjjbhPdnalTmbazhHinJbbbbJbbjZaOaHydbgrc8S2fgvIdygw:vawJbbbb9BEavIdwaxcwfIdbgwNavIdzaxIdbgCNavIdaMgLaLMMawNavIdlaxclfIdbgLNavIdCawNavId3MgwawMMaLNavIdbaCNavIdxaLNavIdKMgwawMMaCNavId8KMMM:lNhwdndnaParcdtgvfgrydbcuSmbaiavfIdbaw9ETmekaraABdbaiavfawUdbkaHclfhHaxcxfhxalaAcefgA9hmbkkdndnaXmbJbbbbhwxekJbbbbhwinaiIdbgCawawaC9DEhwaiclfhiaXcufgXmbkaw:rhwkakcd4akfhOcehiinaigvcethiavaO6mbkcbhOaqcuavcdtgiavcFFFFi0Ecbyd;y:L:cjbHjjjjbbgHBdyaHcFeaiz:xjjjbhXdnadTmbavcufhrcbhkcbhxindnazaeaxcdtfgvydbcdtfydbgiazavclfydbcdtfydbgOSmbaiazavcwfydbcdtfydbgvSmbaOavSmbaPavcdtfydbhAdndnaPaOcdtfydbgvaPaicdtfydbgi9pmbavaA9pmbaAhlaihoavhAxekdnaAai9pmbaAav9pmbaihlavhoxekavhlaAhoaihAkabakcx2fgvaABdbavcwfaoBdbavclfalBdbdnaXaoc:3F;N8N2alc:F:b:DD27aAc;D;O:B8J27arGgOcdtfgvydbgicuSmbcehHinaHhvdnabaicx2fgiydbaA9hmbaiydlal9hmbaiydwaoSmikavcefhHaXaOavfarGgOcdtfgvydbgicu9hmbkkavakBdbakcefhkkaxcifgxad6mbkakci2hOkcwhvaDTmekaDawUdbkavcdthvaqcxfc98fhiinaiavfydbcbyd;C:L:cjbH:bjjjbbavc98fgvmbkaqc;Wbf8KjjjjbaOk:0iewuabcFeaecdtz:xjjjbhbdnalmbcbskaecufhvdndnaiTmbcbhocbhrindndndnabaiarcdtgwfydbgDcm4aD7c:v;t;h;Ev2gecs4ae7avGgqcdtfgkydbgxcuSmbceheinaiaxcdtgxfydbaDSmdaqaefhxaecefheabaxavGgqcdtfgkydbgxcu9hmbkkakarBdbaoheaocefhoxekadaxfydbhekadawfaeBdbarcefgral9hmbxdkkcbhocbhDindnabaDcm4aD7c:v;t;h;Ev2gecs4ae7avGgqcdtfgkydbgxcuSmbaxaDSmbceheinabaqaefavGgqcdtfgkydbgxcuSmeaecefheaxaD9hmbkkdndnaxcu9hmbakaDBdbaoheaocefhoxekadaxcdtfydbhekadaDcdtfaeBdbaDcefgDal9hmbkkaok:3ldrue9:8Jjjjjbc;Wb9Rgr8Kjjjjbcbhwarcxfcbc;Kbz:xjjjb8AdnabaeSmbabaeadcdtz:wjjjb8AkarcualcdtalcFFFFi0EgDcbyd;y:L:cjbHjjjjbbgqBdxarceBd2aqcbaialavcbarcxfz:djjjbcualcx2alc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbhkarcxfaryd2gxcdtfakBdbaraxcefgmBd2akaialavcbcbz:ejjjb8AarcxfamcdtfaDcbyd;y:L:cjbHjjjjbbgiBdbaraxcdfgvBd2arcxfavcdtfcuaialaeadaqz:fjjjbgecltaecjjjjiGEcbyd;y:L:cjbHjjjjbbgqBdbaqaeaiakalz:gjjjbaxcifhkdnadTmbaoaoNhocbhwabhlcbheindnaqaialydbgvcdtfydbcdtfIdbao9ETmbalclf8PdbhPabawcdtfgDavBdbaDclfaP83dbawcifhwkalcxfhlaecifgead6mbkkdnakTmbaxcdtarcxffcwfhlinalydbcbyd;C:L:cjbH:bjjjbbalc98fhlakcufgkmbkkarc;Wbf8Kjjjjbawk;lOoDud99oue99vuv998Jjjjjbc;Wb9Rgw8KjjjjbdndnarmbcbhDxekawcxfcbc;Kbz:xjjjb8Aawcuadcx2adc;v:Q;v:Qe0Ecbyd;y:L:cjbHjjjjbbgqBdxawceBd2aqaeadaicbcbz:ejjjb8AawcuadcdtadcFFFFi0Egkcbyd;y:L:cjbHjjjjbbgxBdzawcdBd2adcd4adfhecehiinaigmcethiamae6mbkcbhPawcuamcdtgsamcFFFFi0Ecbyd;y:L:cjbHjjjjbbgzBdCawciBd2dndnar:ZgH:rJbbbZMgO:lJbbb9p9DTmbaO:Ohixekcjjjj94hikamcufhAc:bwhCcbhXadhQcbhLinaiaCcufgeaiae9iEaPcefaiaP9kEhDdndnadTmbaDcuf:YhOaqhiaxheadhKindndnaiIdbaONJbbbZMgY:lJbbb9p9DTmbaY:Oh8Axekcjjjj94h8Aka8AcCth8AdndnaiclfIdbaONJbbbZMgY:lJbbb9p9DTmbaY:OhExekcjjjj94hEkaEcqta8AVh8AdndnaicwfIdbaONJbbbZMgY:lJbbb9p9DTmbaY:OhExekcjjjj94hEkaea8AaEVBdbaicxfhiaeclfheaKcufgKmbkazcFeasz:xjjjbh3cbh5cbh8Eindna3axa8Ecdtfydbg8Acm4a8A7c:v;t;h;Ev2gics4ai7aAGgKcdtfgEydbgecuSmbaea8ASmbcehiina3aKaifaAGgKcdtfgEydbgecuSmeaicefhiaea8A9hmbkkaEa8ABdba5aecuSfh5a8Ecefg8Ead9hmbxdkkazcFeasz:xjjjb8Acbh5kdnaQ:ZgYaH:taD:YgOaC:Y:tg8FNaX:Zgaa5:Zgh:tNaaaH:taOaP:Y:tggNahaY:tNMg8JJbbbb9BmbaYaa:taga8FahaH:tNNNa8J:vaOMhOkaPaDa5ar0geEhPaXa5aeEhXdna5arSmbaDaCaeEgCaP9Rcd9imbdndnaLcl0mbdnaOJbbbZMgO:lJbbb9p9DTmbaO:Ohixdkcjjjj94hixekaPaCfcd9Thika5aQaeEhQaLcefgLcs9hmekkdndnaXmbcihicbhDxekawakcbyd;y:L:cjbHjjjjbbg8ABdKawclBd2aPcuf:YhYdnadTmbaqhiaxheadhKindndnaiIdbaYNJbbbZMgO:lJbbb9p9DTmbaO:OhExekcjjjj94hEkaEcCthEdndnaiclfIdbaYNJbbbZMgO:lJbbb9p9DTmbaO:Oh3xekcjjjj94h3ka3cqtaEVhEdndnaicwfIdbaYNJbbbZMgO:lJbbb9p9DTmbaO:Oh3xekcjjjj94h3kaeaEa3VBdbaicxfhiaeclfheaKcufgKmbkkawcuazama8Aaxadz:mjjjbgDc32giaDc;j:KM;jb0Ecbyd;y:L:cjbHjjjjbbgeBd3awcvBd2aecbaiz:xjjjbh3avcd4hxdnadTmbdnalTmbaxcdth8Ea8AhEaqhealhKadhAina3aEydbc32fgiaeIdbaiIdbMUdbaiaeclfIdbaiIdlMUdlaiaecwfIdbaiIdwMUdwaiaKIdbaiIdxMUdxaiaKclfIdbaiIdzMUdzaiaKcwfIdbaiIdCMUdCaiaiIdKJbbjZMUdKaEclfhEaecxfheaKa8EfhKaAcufgAmbxdkka8AhKaqheadhEina3aKydbc32fgiaeIdbaiIdbMUdbaiaeclfIdbaiIdlMUdlaiaecwfIdbaiIdwMUdwaiaiIdxJbbbbMUdxaiaiIdzJbbbbMUdzaiaiIdCJbbbbMUdCaiaiIdKJbbjZMUdKaKclfhKaecxfheaEcufgEmbkkdnaDTmba3hiaDheinaiaiIdbJbbbbJbbjZaicKfIdbgO:vaOJbbbb9BEgONUdbaiclfgKaOaKIdbNUdbaicwfgKaOaKIdbNUdbaicxfgKaOaKIdbNUdbaiczfgKaOaKIdbNUdbaicCfgKaOaKIdbNUdbaic3fhiaecufgembkkcbhEawcuaDcdtgCaDcFFFFi0Egicbyd;y:L:cjbHjjjjbbgeBdaawcoBd2awaicbyd;y:L:cjbHjjjjbbg8EBd8KaecFeaCz:xjjjbh5dnadTmbaoJbbjZJbbjZaY:vaPceSENgOaONhYaxcdthxalheinaYaecN:H:cjbalEgKIdwa3a8AydbgAc32fgiIdC:tgOaONaKIdbaiIdx:tgOaONaKIdlaiIdz:tgOaONMMNaqcwfIdbaiIdw:tgOaONaqIdbaiIdb:tgOaONaqclfIdbaiIdl:tgOaONMMMhOdndna5aAcdtgifgKydbcuSmba8EaifIdbaO9ETmekaKaEBdba8EaifaOUdbka8Aclfh8AaqcxfhqaeaxfheadaEcefgE9hmbkkaba5aCz:wjjjb8Acrhikaicdthiawcxfc98fheinaeaifydbcbyd;C:L:cjbH:bjjjbbaic98fgimbkkawc;Wbf8KjjjjbaDk:Pdidui99ducbhi8Jjjjjbca9Rglcbyd1:G:cjbBdKalcb8Pdj:G:cjb83izalcbydN:G:cjbBdwalcb8Pd:m:G:cjb83ibdndnaembJbbjFhvJbbjFhoJbbjFhrxekadcd4cdthwincbhdinalczfadfgDabadfIdbgvaDIdbgoaoav9EEUdbaladfgDavaDIdbgoaoav9DEUdbadclfgdcx9hmbkabawfhbaicefgiae9hmbkalIdwalIdK:thralIdlalIdC:thoalIdbalIdz:thvkJbbbbavavJbbbb9DEgvaoaoav9DEgvararav9DEk:H8Modui99lud99Aus998Jjjjjbcji9RgD8KjjjjbcbhqaDcxfcbc;Kbz:xjjjb8AaDcbBdwaD9cb83ibaDcbyd;i:L:cjbBd1eaDcb8Pd;a:L:cjb83ijeaDcbyd;u:L:cjbBd94aDcb8Pd;m:L:cjb83i9WdndnavmbJbbjFhkJbbjFhxJbbjFhmxekaocd4cdthPalhsincbhzinaDcjefazfgHasazfIdbgkaHIdbgxaxak9EEUdbaDc;WbfazfgHakaHIdbgxaxak9DEUdbazclfgzcx9hmbkasaPfhsaqcefgqav9hmbkaDId94aDId1e:thmaDIdtaDId:ee:thxaDId9WaDIdje:thkkJbbbbhOdnar:YgAJq;x8J88MaA:vJbbbbakakJbbbb9DEgkaxaxak9DEgkamamak9DENgxJbbbb9Bmbarc9:f:Yax:vhOkaDcCfhCaDcxfcxfhXcbhzinaDazfaDcjefazfIdbgkaxaDc;WbfazfIdbak:t:tJbbb:;NMUdbazclfgzcx9hmbkcbhQaDarar2gLar2gzcbyd;y:L:cjbHjjjjbbgHBdxaDceBd2aHcbazz:xjjjbgKcbcbadaialaoaraOaDawz:rjjjbcdhYaDcuaLcdtaLcFFFFi0Eg8Acbyd;y:L:cjbHjjjjbbgEBdzaDcdBd2aDcjefcbarz:xjjjb8Acbh3dnaLTmbdnarcb9kmbaKhzaEhHaLhsincbh3aHcbcuazaDcjefarz:AjjjbEBdbazarfhzaHclfhHascufgsmbxdkkaKhPcbh3cbhvindndnaKavar2faDcjefarz:AjjjbTmbcbhHaPhzarhsinazaHazRbbgqfgHcbaqE86bbazcefhzascufgsmbkaEavcdtfa3BdbaHa3fh3xekaEavcdtfcuBdbkaParfhPavcefgvaL9hmbkkdnabTmbaDcua3cotgza3cFFF8F0Ecbyd;y:L:cjbHjjjjbbgQBdCcihYaDciBd2aQcbazz:xjjjb8AaXhCkdnawceGmbaCa8Acbyd;y:L:cjbHjjjjbbg5BdbaDaYcefgzBd2aDcxfazcdtfaLcbyd;y:L:cjbHjjjjbbgzBdbaDaYcdfgYBd2azcbaLz:xjjjbh8EarcufhXdnarci9imbarc9:fhCararcef2aKfcefh8Aceh8Fina8Far2hPa8AhvcehqindnaEaqaPfcdtfydbcuSmbavhzaChHinazazRbbgscuasE86bbazcefhzaHcufgHmbkkavarfhvaqcefgqaX9hmbka8AaLfh8Aa8Fcefg8FaX9hmbkkarce9imbcbh8Acbhqcbhvina8EaqfhscbhzindnasazfgHRbbmbaHce86bba5a8AcdtfaqazfBdba8Acefh8Akarazcefgz9hmbkaqarfhqavcefgvar9hmbka8ATmbaKcefhaaKc9:fhharc9:fhgarci9ih8Jina8Ea5a8Acufg8Acdtfydbgvfcb86bbavar2hPdna8JmbaEavcdtfydbcuSmbaKaPfhHaghqindnaHcefgzRbbgscFe9hmbaHRbbmbcbhskazas86bbazhHaqcufgqmbkaharavcef2fhzaXhsindnazRbbgHcFe9hmbazcefRbbmbcbhHkazaH86bbazcufhzascufgsce9kmbkkaaaPfh8Kavavar9Ug8Lar29Rh8FcbhCindnaCceScuaCEa8Ffgzce9imbazaX9ombcuaCciSaCcdSEa8LfgHce9imbaHaX9ombaEaHar2azfg8McdtfydbcuSmba8Jmbaaa8Mar2fhzcbhqa8KhsaghvinazazRbbgHcbaHaHcFeSEasRbbEgP86bbascefhsazcefhzaPaH7aqVhqavcufgvmbkaqcFeGTmba8Ea8MfgzRbbmbazce86bba5a8Acdtfa8MBdba8Acefh8AkaCcefgCcl9hmbka8AmbkkdnaQTmbaKaEaQadaialaoaraOaDawz:rjjjba3TmbJbbjZaO:vhkawcjjjjlGhPdnawcdGTmbJbbnnaOaON:vh8NakJbbbZNhyaQhzinazczfgsIdbg8PazcCfIdbgx:vhmazcxfgqIdbgIax:vhAazcwfgvIdbg8Rax:vh8SakazydbgHcFrG:ZNhRakaHcq4cFrG:ZNh8UakaHcC4cFrG:ZNh8VdnaxJ:p;c;188Ng8WazcKfIdbMg8X:laxJ:983:g81Ngx9ETmba8Wazc3fIdbMazc8KfIdbg8Ya8Ya8X:vg8YN:tg8Z:lax9ETmba8WazcafIdbMazcyfIdbg8Wa8Wa8X:vg80N:tazc8SfIdba8Wa8YN:tg8Wa8Wa8Z:vg8WN:tg81:lax9ETmba8PJ:p;c;188NazcUfIdb:ta80a8RJ:p;c;188Nazc8WfIdb:tg8PN:ta8WaIJ:p;c;188Nazc80fIdb:ta8Ya8PN:tgIN:ta81:vgxam:tg8Ra8RNa8Pa8X:va8YaIa8Z:va8WaxN:tg8XN:ta80axN:tg8Wa8S:tg8Ya8YNa8XaA:tg8Ya8YNMMa8N9DTmbaxaRaxaR9EEgxakaRMgmaxam9DEhma8Xa8Ua8Xa8U9EEgxaka8UMgAaxaA9DEhAa8Wa8Va8Wa8V9EEgxaka8VMg8Saxa8S9DEh8SkdnaPTmbayaRMhmaya8UMhAaya8VMh8SkasamUdbaqaAUdbava8SUdbazc;abfhza3cufg3mbxdkkdnaPTmbakJbbbZNhxaQhzinazczfaxakazydbgHcFrG:ZNMUdbazcxfaxakaHcq4cFrG:ZNMUdbazcwfaxakaHcC4cFrG:ZNMUdbazc;abfhza3cufg3mbxdkkaQcCfhzinazc98fgHaHIdbazIdbgk:vUdbazc94fgHaHIdbak:vUdbazctfgHaHIdbak:vUdbazc;abfhza3cufg3mbkkcbhsdndnarcd9imbarcufh3aEarcdtfhadnabmbaKcefg8Mararcefgz2fh8JaKazfhba8MaLfh8Ecbhscbh8Kina8Kar2h8La8Mheabh8Aa8Eh8Fa8Jh5cbhXindnaEaXa8LfgqcdtgzfgHclfydbaHydbGaaazfgzydbGazclfydbGcuSmbclcbaKaqar2fgzarfRbbEazRbbcb9hVczcbazaLfgzRbbEVc;abcbazarfRbbEVhPaehza8AhHa8Fhqa5hva3hQindnaPclcbaHRbbEazRbbcb9hVczcbaqRbbEVc;abcbavRbbEVgPcetVgCTmbaCcFeSmbasaCRb;W;p:cjbfhskazcefhzaHcefhHaqcefhqavcefhvaQcufgQmbkkaearfhea8Aarfh8Aa8Farfh8Fa5arfh5aXcefgXa39hmbka8MaLfh8MabaLfhba8EaLfh8Ea8JaLfh8Ja8Kcefg8Ka39hmbxdkkJbbjZaO:vgkakJk;x8J88NNh8RawcdGh8EaDIdwhkaDIdlhxaDIdbhmcbhscbhPinaPar2h8KcbhvindnaEava8KfgqcdtgzfgHclfydbaHydbGaaazfgzydbGazclfydbGcuSmbcbh8AclcbaKaqar2fgYarfRbbEaYRbbcb9hVczcbaYaLfg8JRbbEVc;abcba8JarfRbbEVh8Lindna8LclcbaYa8Ag8Mcefg8AfgzarfRbbEazRbbcb9hVczcba8Ja8AfgzRbbEVc;abcbazarfRbbEVg8LcetVgCTmbaCcFeSmbcbhqdndndnaCRb;W;n:cjbcufPdebdka8ETmeaCcC2gz8Ve;W:L:cjbcltaz8Ve;Y:L:cjbcsGVh8FaKa8Mfh5cxhzaDcjefhHinaHaQaEa8Faz4gqce4ceGavfaqcd4ceGaPfar2fgXcdtfydbcotfa5aqceGfaXar2fRbbcotfcnfBdbaHclfhHazc98fgzc989hmbkaDydjegzIdyaDyd:megHIdyMaDyd:eegqIdyaDyd1egXIdyMMg8XaqIdwaXIdwMJbbbZNgANazIdUaHIdUMaqIdUaXIdUMMg8WMg8Sa8SMazIdaaHIdaMaqIdaaXIdaMMg8YaqIdzaXIdzMJbbbZNg8SNMa8SNazId8SaHId8SMaqId8SaXId8SMMgRa8SNazId80aHId80MaqId80aXId80MMg8UMg8Sa8SMazId3aHId3MaqId3aXId3MMg8VaqIdxaXIdxMJbbbZNg8SNMa8SNazId8KaHId8KMaqId8KaXId8KMMg8Za8SNazId8WaHId8WMaqId8WaXId8WMMg80Mg8Sa8SMazIdKaHIdKMaqIdKaXIdKMMgyaANMaANazId88aHId88MaqId88aXId88MMg8PMMM:lgIa8RazIdCaHIdCMaqIdCaXIdCMMN9Ea8XazIdwaHIdwMJbbbZNgANa8WMg8Sa8SMa8YazIdzaHIdzMJbbbZNg8SNMa8SNaRa8SNa8UMg8Sa8SMa8VazIdxaHIdxMJbbbZNg8SNMa8SNa8Za8SNa80Mg8Sa8SMayaANMaANa8PMMM:laIJ;d;1UZN9DGhqxekaKa8Mfh8FcbhzcrhHindnaCaz4ceGTmba8FazceGfazce4ceGavfazcd4aPfar2fgqar2fRbbgXcFeSmbaQaEaqcdtfydbcotfaXcotfc9efRbbaH4ceGTmbcbhqxdkaHcufhHcehqazcefgzcw9hmbkkaCcC2aqcq2fgH8Ve;W:L:cjbgzTmbaHc;Y:L:cjbfhqaKa8MfhCabasc8K2fhHindnasae9pmbaHaQaEazcD4ceGavfazcq4ceGaPfar2fgXcdtfydbcotfaCazcw4ceGfaXar2fRbbcotfgXc9ifIdbamMUdbaHclfaXc9mfIdbaxMUdbaHcwfaXc9qfIdbakMUdbaHcxfamaQaEazcv4ceGavfazco4ceGaPfar2fgXcdtfydbcotfaCazcl4ceGfaXar2fRbbcotfgXc9ifIdbMUdbaHczfaxaXc9mfIdbMUdbaHcCfakaXc9qfIdbMUdbaHcKfamaQaEazce4ceGavfazcd4ceGaPfar2fgXcdtfydbcotfaCazceGfaXar2fRbbcotfgzc9ifIdbMUdbaHc3faxazc9mfIdbMUdbaHcafakazc9qfIdbMUdbkaHc8KfhHascefhsaq8Vebhzaqcdfhqazmbkka8Aa39hmbkkavcefgva39hmbkaPcefgPa39hmbkaDyd2gYTmekaYcdtaDcxffc98fhzinazydbcbyd;C:L:cjbH:bjjjbbazc98fhzaYcufgYmbkkaDcjif8Kjjjjbask;Kxmiue99due99euz99eui99eud99dud99oudnalTmbaocd4hkaqcdGhxarc99fhqarcethmawawMhPcbhsindndnawavaiascdtfgoclfydbak2cdtfgzIdwgHavaoydbak2cdtfgOIdwgA:tgCaCNazIdbgXaOIdbgQ:tgLaLNazIdlgKaOIdlgY:tg8Aa8ANMMgEavaocwfydbak2cdtfgoIdwg3aA:tg5a5NaoIdbg8EaQ:tg8Fa8FNaoIdlgaaY:tghahNMMggaEag9EEgEa3aH:tgHaHNa8EaX:tgHaHNaaaK:tgHaHNMMgHaEaH9EE:rNgHaHMgH:lJbbb9p9DTmbaH:Ohoxekcjjjj94hokdnaLahNa8Aa8FN:tgHaHNa8Aa5NaCahN:tgXaXNaCa8FNaLa5N:tgKaKNMMg3Jbbbb9BmbJbbjZhEdnaoceaoce9kEgoamaoam9iEg8Jcd9imbJbbjZa8J:Z:vhEkarcb9imbaAaDIdw:th8KaYaDIdl:th8LaQaDIdb:th8Ma8Jcba8Jcb9kEh8NdnadTmbaHJbbjZa3:rgA:vgQNg3aAa8Jcefa8Jcdf2:Y:vgANh8EaKaQNgKaANhyaXaQNgXaXaANNh8PcbhIina8Jcba8Jcb9kEcefh8RaEaI:ZNgQaCNa8KMhgaQa8ANa8LMh8SaQaLNa8MMhRcbhzindndnaPaEaz:ZNgQahNa8SMgYNgH:lJbbb9p9DTmbaH:OhOxekcjjjj94hOkaOce91goaqaoaq6Eh8UdndnaPaQa5NagMgHNga:lJbbb9p9DTmbaa:Oh8Vxekcjjjj94h8Vka8Ua8Vce91goaqaoaq6Eg8Wcefar2fcefgoar2h8XdndnaPaQa8FNaRMgQNga:lJbbb9p9DTmbaa:Oh8Yxekcjjjj94h8Ykadaeaocdtfydbcotfaba8Yce91goaqaoaq6Eg8Zfa8XfcefRbbcotfgocnfa8Ucqta8ZcCtVa8WVBdbaoc9efg8Ua8URbbcea8YceGaOcetcdGVa8VcdtclGVtV86bbaoc9ifgOaQaANaOIdbMUdbaoc9mfgOaYaANaOIdbMUdbaoc9qfgOaHaANaOIdbMUdbaoc9ufgOaAaOIdbMUdbdnaxTmbaoc9yfgOa8PaOIdbMUdbaoc9CfgOaKayNaOIdbMUdbaoc9GfgOa3a8ENaOIdbMUdbaoc9KfgOaXayNaOIdbMUdbaoc9OfgOaXa8ENaOIdbMUdbaoc2fgOaKa8ENaOIdbMUdbaoc9WfgOaXaAa3aHNaXaQNaKaYNMMgY:mNgQNaOIdbMUdbaoctfgOaKaQNaOIdbMUdbaoc94fgOa3aQNaOIdbMUdbaoc98fgoaoIdbaYaQN:tUdbka8Razcefgz9hmbka8Jcufh8JaIa8NShoaIcefhIaoTmbxdkkcbh8Vina8Jcba8Jcb9kEcefh8UaEa8V:ZNgAaCNa8KMhYaAa8ANa8LMhHaAaLNa8MMhXcbhoindndnaPaEao:ZNgAahNaHMNgQ:lJbbb9p9DTmbaQ:Ohzxekcjjjj94hzkazce91gzaqazaq6EhzdndnaPaAa5NaYMNgQ:lJbbb9p9DTmbaQ:OhOxekcjjjj94hOkazaOce91gOaqaOaq6Ecefar2fcefar2hzdndnaPaAa8FNaXMNgA:lJbbb9p9DTmbaA:OhOxekcjjjj94hOkabaOce91gOaqaOaq6Efazfcefce86bba8Uaocefgo9hmbka8Jcufh8Ja8Va8NShoa8Vcefh8VaoTmbkkascifgsal6mbkkk:Nvezu8Jjjjjbcjd9Rgb8Kjjjjbcbheabcbcjdz:xjjjbhdc:W:H:cjbhbinabRbbgicC2glabcqf8Veb87e;4:L:cjbalabcdfgv8Peb83e;W:L:cjbaiabcefRbb86b;W;n:cjbadaifce86bbalavabcxfceaetc:F:d;avGEgi8Peb83e;6:L:cjbalai8Vew87e:c:M:cjbabcQfhbaecefgecK9hmbkcbhoinc;Y:L:cjbhrcbhvindnadavfgwRbbce9hmbavcC2c;W:L:cjbfhDcbhbcehqavc;W;n:cjbfhkinabcitc:G:H:cjbfhlcbhbcbheinaeavab4ceGalabfRbbtVheabcefgbcw9hmbkdnadaecFeGgxfgmRbbmbaxcC2c;W:L:cjbfhPcbhbcehsindnaDabcq2gif8VebgbTmbaraifheaPaifhiinaialabcl4csGfRbbcltalabcw4csGfRbbcwtValabcsGfRbbV87ebaicdfhiae8VebhbaecdfheabmbkkcehbasceGhecbhsaembkamce86bbaxakRbb86b;W;n:cjbkcehbaqceGhlcbhqalmbkawcd86bbkarcCfhravcefgvcjd9hmbkaocefgoci9hmbkcbhic;W:L:cjbhvincuhlavhbinalcefhlab8Vebheabcdfhbaembkaial86b;W;p:cjbavcCfhvaicefgicjd9hmbkadcjdf8Kjjjjbk9DeeuabcFeaicdtz:xjjjbhlcbhbdnadTmbindnalaeydbcdtfgiydbcu9hmbaiabBdbabcefhbkaeclfheadcufgdmbkkabk;Bidqui998Jjjjjbc;Wb9Rgl8Kjjjjbalcxfcbc;Kbz:xjjjb8Aadcd4adfhvcehoinaogrcethoarav6mbkalcuarcdtgoarcFFFFi0Ecbyd;y:L:cjbHjjjjbbgvBdxavcFeaoz:xjjjbhwdnadTmbaicd4hDarcufhqcbhkindndnawcbaeakaD2cdtfgrydlgiaicjjjj94SEgocH4ao7c:F:b:DD2cbarydbgxaxcjjjj94SEgocH4ao7c;D;O:B8J27cbarydwgmamcjjjj94SEgrcH4ar7c:3F;N8N27aqGgvcdtfgrydbgocuSmbam::hPai::hsax::hzcehiinaihrdnaeaoaD2cdtfgiIdbaz9CmbaiIdlas9CmbaiIdwaP9BmikarcefhiawavarfaqGgvcdtfgrydbgocu9hmbkkarakBdbakhokabakcdtfaoBdbakcefgkad9hmbkkalydxcbyd;C:L:cjbH:bjjjbbalc;Wbf8Kjjjjbk9teiucbcbyd;G:L:cjbgeabcifc98GfgbBd;G:L:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaik;LeeeudndnaeabVciGTmbabhixekdndnadcz9pmbabhixekabhiinaiaeydbBdbaiclfaeclfydbBdbaicwfaecwfydbBdbaicxfaecxfydbBdbaeczfheaiczfhiadc9Wfgdcs0mbkkadcl6mbinaiaeydbBdbaeclfheaiclfhiadc98fgdci0mbkkdnadTmbinaiaeRbb86bbaicefhiaecefheadcufgdmbkkabk;aeedudndnabciGTmbabhixekaecFeGc:b:c:ew2hldndnadcz9pmbabhixekabhiinaialBdbaicxfalBdbaicwfalBdbaiclfalBdbaiczfhiadc9Wfgdcs0mbkkadcl6mbinaialBdbaiclfhiadc98fgdci0mbkkdnadTmbinaiae86bbaicefhiadcufgdmbkkabk9teiucbcbyd;G:L:cjbgeabcrfc94GfgbBd;G:L:cjbdndnabZbcztgd9nmbcuhiabad9RcFFifcz4nbcuSmekaehikaikTeeucbabcbyd;G:L:cjbge9Rcifc98GaefgbBd;G:L:cjbdnabZbcztge9nmbabae9RcFFifcz4nb8Akk6eiucbhidnadTmbdninabRbbglaeRbbgv9hmeaecefheabcefhbadcufgdmbxdkkalav9Rhikaikk;0vdbcj:Gdk;yvFFuuFFuuFFuuFFuFFFuFFFuFbbbbbbbbebbbdbbbbbbbebbbebbbdbbbbbbbbbbbeeeeeebebbeebbebbebbbeeebbbbebbbbbbbbbbbbbbbbbbbeeeeeeebebbbeeebbeebbbbbebbbbbebebbbbbbbbbbbbbbbdiorbelvlbodveribbbbbbbbbbbbbbbbbbbbbbebbbbbbbbbbbbbbbbbbbbbibbbbbbbbbbbbbbbbbbbbbobbbbbbbbbbbbbbbbbbbbbrbaebbbbbbbbbbbbbbbbbbsd8We8YbbbbbbbhiaebbbbbbQe8Ke9cebbbbbbbbbbbbbbbbLb8KebbbbbbbbbbbbbbbbbbKbbbbbbbbbbbbbbbbbbbbbYeJbilbbbbbbbbbbbbbbbbEe80e8WlbbbbbbzlAbbbbbbb5eJdnibbbbbbai8Kbbbbbbb8Ee9ce8Ylcibbbb8Yebbbbbbbb8FdOlAdbbbbbb80e8Ylbbbbbb88eTi8KiJv8Jlbbbbbbbbbbbb89e9td8Kv9qibbbbndlvaibbbbZd8Li8KvbbbbbbJdTibbbbbb9Pe81b9GvoiBvbbbbbbbbbbbb9Re9JbvoWibbbbvibbbbbbbb9VeWi9Gvbbbbbb8WvBbbbbbbb9:b9ceBvbbbbbbbbbbbbbbbbubWibbbbbbbbbbbbbbbbbb;Wd9hvSrbbbbbbWl9NvbbbbbbFbbbbbbbbbbbbbbbbbbbbbFFuuFFuuFFuuFFuFFFuFFFuFbc;y:Ldkxebbbdbbb;W:Obb",t=new Uint8Array([32,0,65,2,1,106,34,33,3,128,11,4,13,64,6,253,10,7,15,116,127,5,8,12,40,16,19,54,20,9,27,255,113,17,42,67,24,23,146,148,18,14,22,45,70,69,56,114,101,21,25,63,75,136,108,28,118,29,73,115]);if(typeof WebAssembly!="object")return{supported:!1};var e,n=WebAssembly.instantiate(a(i),{}).then(function(p){e=p.instance,e.exports.__wasm_call_ctors()});function a(p){for(var _=new Uint8Array(p.length),S=0;S<p.length;++S){var b=p.charCodeAt(S);_[S]=b>96?b-97:b>64?b-39:b+4}for(var M=0,S=0;S<p.length;++S)_[M++]=_[S]<60?t[_[S]]:(_[S]-60)*64+_[++S];return _.buffer.slice(0,M)}function s(p){if(!p)throw new Error("Assertion failed")}function r(p){return new Uint8Array(p.buffer,p.byteOffset,p.byteLength)}function o(p,_,S,b){var M=e.exports.sbrk,E=M(S*4),A=M(S*b*4),I=new Uint8Array(e.exports.memory.buffer);I.set(r(_),A),p(E,A,S,b*4),I=new Uint8Array(e.exports.memory.buffer);var N=new Uint32Array(S);return new Uint8Array(N.buffer).set(I.subarray(E,E+S*4)),M(E-M(0)),N}function c(p,_,S){var b=e.exports.sbrk,M=b(_.length*4),E=b(S*4),A=new Uint8Array(e.exports.memory.buffer),I=r(_);A.set(I,M);var N=p(E,M,_.length,S);A=new Uint8Array(e.exports.memory.buffer);var L=new Uint32Array(S);new Uint8Array(L.buffer).set(A.subarray(E,E+S*4)),b(M-b(0));for(var P=0;P<_.length;++P)_[P]=L[_[P]];return[L,N]}function l(p){for(var _=0,S=0;S<p.length;++S){var b=p[S];_=_<b?b:_}return _}function h(p,_,S,b,M,E,A,I,N){var L=e.exports.sbrk,P=L(4),U=L(S*4),V=L(M*E),O=L(S*4),Q=new Uint8Array(e.exports.memory.buffer);Q.set(r(b),V),Q.set(r(_),O);var G=p(U,O,S,V,M,E,A,I,N,P);Q=new Uint8Array(e.exports.memory.buffer);var Z=new Uint32Array(G);r(Z).set(Q.subarray(U,U+G*4));var et=new Float32Array(1);return r(et).set(Q.subarray(P,P+4)),L(P-L(0)),[Z,et[0]]}function u(p,_,S,b,M,E,A,I,N,L,P,U,V){var O=e.exports.sbrk,Q=O(4),G=O(S*4),Z=O(M*E),et=O(M*I),ht=O(N.length*4),Pt=O(S*4),Y=L?O(M):0,ct=new Uint8Array(e.exports.memory.buffer);ct.set(r(b),Z),ct.set(r(A),et),ct.set(r(N),ht),ct.set(r(_),Pt),L&&ct.set(r(L),Y);var mt=p(G,Pt,S,Z,M,E,et,I,ht,N.length,Y,P,U,V,Q);ct=new Uint8Array(e.exports.memory.buffer);var Tt=new Uint32Array(mt);r(Tt).set(ct.subarray(G,G+mt*4));var gt=new Float32Array(1);return r(gt).set(ct.subarray(Q,Q+4)),O(Q-O(0)),[Tt,gt[0]]}function d(p,_,S,b,M,E,A,I,N,L,P,U,V){var O=e.exports.sbrk,Q=O(4),G=O(M*E),Z=O(M*I),et=O(N.length*4),ht=O(S*4),Pt=L?O(M):0,Y=new Uint8Array(e.exports.memory.buffer);Y.set(r(b),G),Y.set(r(A),Z),Y.set(r(N),et),Y.set(r(_),ht),L&&Y.set(r(L),Pt);var ct=p(ht,S,G,M,E,Z,I,et,N.length,Pt,P,U,V,Q);Y=new Uint8Array(e.exports.memory.buffer),r(_).set(Y.subarray(ht,ht+ct*4)),r(b).set(Y.subarray(G,G+M*E)),r(A).set(Y.subarray(Z,Z+M*I));var mt=new Float32Array(1);return r(mt).set(Y.subarray(Q,Q+4)),O(Q-O(0)),[ct,mt[0]]}function f(p,_,S,b){var M=e.exports.sbrk,E=M(S*b),A=new Uint8Array(e.exports.memory.buffer);A.set(r(_),E);var I=p(E,S,b);return M(E-M(0)),I}function x(p,_,S,b,M,E,A,I){var N=e.exports.sbrk,L=N(I*4),P=N(S*b),U=M?N(S*E):0,V=new Uint8Array(e.exports.memory.buffer);V.set(r(_),P),M&&V.set(r(M),U);var O=p(L,P,S,b,U,E,A,I);V=new Uint8Array(e.exports.memory.buffer);var Q=new Uint32Array(O);return r(Q).set(V.subarray(L,L+O*4)),N(L-N(0)),Q}function v(p,_,S,b,M,E,A,I,N){var L=e.exports.sbrk,P=L(4),U=L(S*4),V=L(M*E),O=L(S*4),Q=A?L(M):0,G=new Uint8Array(e.exports.memory.buffer);G.set(r(b),V),G.set(r(_),O),A&&G.set(r(A),Q);var Z=p(U,O,S,V,M,E,Q,I,N,P);G=new Uint8Array(e.exports.memory.buffer);var et=new Uint32Array(Z);r(et).set(G.subarray(U,U+Z*4));var ht=new Float32Array(1);return r(ht).set(G.subarray(P,P+4)),L(P-L(0)),[et,ht[0]]}function m(p,_,S,b,M,E,A){var I=e.exports.sbrk,N=I(S*4),L=I(M*E),P=I(S*4),U=new Uint8Array(e.exports.memory.buffer);U.set(r(b),L),U.set(r(_),P);var V=p(N,P,S,L,M,E,A);U=new Uint8Array(e.exports.memory.buffer);var O=new Uint32Array(V);return r(O).set(U.subarray(N,N+V*4)),I(N-I(0)),O}function g(p,_,S,b,M,E){var A=e.exports.sbrk,I=A(S.byteLength),N=A(_.byteLength),L=new Uint8Array(e.exports.memory.buffer);L.set(r(S),I),L.set(r(_),N);var P=S.byteLength/b,U=p(0,0,N,_.length,I,P,b,M,E),V=A(U*9*4),O=p(V,U,N,_.length,I,P,b,M,E);s(O<=U),L=new Uint8Array(e.exports.memory.buffer);var Q=new Float32Array(O*9);return r(Q).set(L.subarray(V,V+Q.byteLength)),A(I-A(0)),Q}var y={LockBorder:1,Sparse:2,ErrorAbsolute:4,Prune:8,Regularize:16,Permissive:32,RegularizeLight:64,PreserveFolds:128,ErrorClamped:256,_InternalDebug:1<<30},w={Shell:1,Solve:2,Thicken:0,_InternalDebug:1<<30};return{ready:n,supported:!0,compactMesh:function(p){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0);var _=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),S=c(e.exports.meshopt_optimizeVertexFetchRemap,_,l(p)+1);if(p!==_)for(var b=0;b<_.length;++b)p[b]=_[b];return S},generatePositionRemap:function(p,_){return s(p instanceof Float32Array),s(p.length%_==0),s(_>=3),o(e.exports.meshopt_generatePositionRemap,p,p.length/_,_)},simplify:function(p,_,S,b,M,E){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(_ instanceof Float32Array),s(_.length%S==0),s(S>=3),s(b>=0&&b<=p.length),s(b%3==0),s(M>=0);for(var A=0,I=0;I<(E?E.length:0);++I)s(E[I]in y),A|=y[E[I]];var N=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),L=h(e.exports.meshopt_simplify,N,p.length,_,_.length/S,S*4,b,M,A);return L[0]=p instanceof Uint32Array?L[0]:new p.constructor(L[0]),L},simplifyWithAttributes:function(p,_,S,b,M,E,A,I,N,L){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(_ instanceof Float32Array),s(_.length%S==0),s(S>=3),s(b instanceof Float32Array),s(b.length==M*(_.length/S)),s(M>=0),s(A==null||A instanceof Uint8Array),s(A==null||A.length==_.length/S),s(I>=0&&I<=p.length),s(I%3==0),s(N>=0),s(Array.isArray(E)),s(M>=E.length),s(E.length<=32);for(var P=0;P<E.length;++P)s(E[P]>=0);for(var U=0,P=0;P<(L?L.length:0);++P)s(L[P]in y),U|=y[L[P]];var V=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),O=u(e.exports.meshopt_simplifyWithAttributes,V,p.length,_,_.length/S,S*4,b,M*4,new Float32Array(E),A,I,N,U);return O[0]=p instanceof Uint32Array?O[0]:new p.constructor(O[0]),O},simplifyWithUpdate:function(p,_,S,b,M,E,A,I,N,L){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(_ instanceof Float32Array),s(_.length%S==0),s(S>=3),s(b instanceof Float32Array),s(b.length==M*(_.length/S)),s(M>=0),s(A==null||A instanceof Uint8Array),s(A==null||A.length==_.length/S),s(I>=0&&I<=p.length),s(I%3==0),s(N>=0),s(Array.isArray(E)),s(M>=E.length),s(E.length<=32);for(var P=0;P<E.length;++P)s(E[P]>=0);for(var U=0,P=0;P<(L?L.length:0);++P)s(L[P]in y),U|=y[L[P]];var V=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),O=d(e.exports.meshopt_simplifyWithUpdate,V,p.length,_,_.length/S,S*4,b,M*4,new Float32Array(E),A,I,N,U);if(p!==V)for(var P=0;P<O[0];++P)p[P]=V[P];return O},getScale:function(p,_){return s(p instanceof Float32Array),s(p.length%_==0),s(_>=3),f(e.exports.meshopt_simplifyScale,p,p.length/_,_*4)},simplifyPoints:function(p,_,S,b,M,E){return s(p instanceof Float32Array),s(p.length%_==0),s(_>=3),s(S>=0&&S<=p.length/_),b?(s(b instanceof Float32Array),s(b.length%M==0),s(M>=3),s(p.length/_==b.length/M),x(e.exports.meshopt_simplifyPoints,p,p.length/_,_*4,b,M*4,E||0,S)):x(e.exports.meshopt_simplifyPoints,p,p.length/_,_*4,void 0,0,0,S)},simplifySloppy:function(p,_,S,b,M,E){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(_ instanceof Float32Array),s(_.length%S==0),s(S>=3),s(b==null||b instanceof Uint8Array),s(b==null||b.length==_.length/S),s(M>=0&&M<=p.length),s(M%3==0),s(E>=0);var A=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),I=v(e.exports.meshopt_simplifySloppy,A,p.length,_,_.length/S,S*4,b,M,E);return I[0]=p instanceof Uint32Array?I[0]:new p.constructor(I[0]),I},simplifyPrune:function(p,_,S,b){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(_ instanceof Float32Array),s(_.length%S==0),s(S>=3),s(b>=0);var M=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p),E=m(e.exports.meshopt_simplifyPrune,M,p.length,_,_.length/S,S*4,b);return E=p instanceof Uint32Array?E:new p.constructor(E),E},remesh:function(p,_,S,b,M){s(p instanceof Uint32Array||p instanceof Int32Array||p instanceof Uint16Array||p instanceof Int16Array),s(p.length%3==0),s(_ instanceof Float32Array),s(_.length%S==0),s(S>=3),s(b>=4&&b<=256);for(var E=0,A=0;A<(M?M.length:0);++A)s(M[A]in w),E|=w[M[A]];var I=p.BYTES_PER_ELEMENT==4?p:new Uint32Array(p);return g(e.exports.meshopt_remesh,I,_,S*4,b,E)}}})();var sg=".tnm-root{--tnm-bg: #fff;--tnm-fg: #1a1a1a;--tnm-muted: #4a4f5c;font:15px/1.4 system-ui,-apple-system,Segoe UI,Roboto,sans-serif;color:var(--tnm-fg);max-width:100%}.tnm-root.tnm-dark{--tnm-bg: #1b1d24;--tnm-fg: #f2f2f2;--tnm-muted: #c3c7d1}.tnm-toolbar{display:flex;flex-wrap:wrap;gap:6px;margin:0 0 6px}.tnm-button{font:inherit;font-size:14px;line-height:1.2;padding:6px 9px;min-height:34px;border-radius:6px;cursor:pointer;border:1px solid var(--tnm-muted);background:var(--tnm-bg);color:var(--tnm-fg)}.tnm-button[aria-pressed=true]{background:var(--tnm-fg);color:var(--tnm-bg)}.tnm-button:focus-visible,.tnm-face-input:focus-visible{outline:3px solid #0072B2;outline-offset:2px}.tnm-stage{position:relative;width:100%;height:380px;max-height:70vh;min-height:220px;border:1px solid var(--tnm-muted);border-radius:0;overflow:hidden;touch-action:pan-y}.tnm-stage:focus-visible{outline:3px solid #0072B2;outline-offset:-3px}.tnm-touch-active .tnm-stage{touch-action:none;outline:3px solid #0072B2;outline-offset:-3px}.tnm-stage canvas{display:block;width:100%;height:100%}.tnm-legend{list-style:none;margin:6px 0 0;padding:0;display:flex;flex-wrap:wrap;gap:4px 16px;font-size:14px}.tnm-key{display:flex;align-items:center;gap:6px;margin:0}.tnm-swatch{display:inline-block;flex:none;width:18px;border:1px solid var(--tnm-muted)}.tnm-swatch-face{height:14px;background:var(--tnm-swatch)}.tnm-swatch-line{height:0;border:0;border-top:4px solid var(--tnm-swatch)}.tnm-hint{font-size:14px;margin:6px 0 0;color:var(--tnm-muted)}.tnm-nogl{padding:12px;border:1px solid var(--tnm-muted)}.tnm-pick{margin:6px 0 0;padding:6px 10px;border:1px solid var(--tnm-muted);border-radius:6px;font-size:15px}.tnm-pick-title{margin:0 0 4px;font-weight:600}.tnm-pick-rows{display:grid;grid-template-columns:max-content 1fr;gap:2px 12px;margin:0}.tnm-pick-rows dt{margin:0}.tnm-pick-rows dd{margin:0;font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;overflow-wrap:anywhere}.tnm-keys{display:flex;flex-wrap:wrap;align-items:center;gap:6px;margin:6px 0 0}.tnm-keys[hidden]{display:none}.tnm-face-label{font-size:14px}.tnm-face-input{font:inherit;font-size:15px;width:8.5em;min-height:34px;padding:4px 6px;border:1px solid var(--tnm-muted);border-radius:6px;background:var(--tnm-bg);color:var(--tnm-fg)}.tnm-button[hidden]{display:none}";var rg="trinormal-mesh-style";function vM(i){if(i.getElementById(rg))return;let t=i.createElement("style");t.id=rg,t.textContent=sg,i.head.appendChild(t)}function Ne(i,t,e){let n=document.createElement(i);return t&&(n.className=t),e!==void 0&&(n.textContent=e),n}function og(i,t,e,n,a){let s=new Float32Array(6*e.length);for(let r=0;r<e.length;r++){let o=e[r],c=t[o],l=t[o%3===2?o-2:o+1];for(let h=0;h<3;h++)s[6*r+h]=(i[3*c+h]-a[h])*n,s[6*r+3+h]=(i[3*l+h]-a[h])*n}return s}function cg(i){let t=new Int32Array(3*i.length);for(let e=0;e<i.length;e++)for(let n=0;n<3;n++)t[3*e+n]=3*i[e]+n;return t}var lg=2e3,MM=6e3,SM=3e4;function wM(i,t,e){let n=new Map;for(let a=0;a<t.length;a++)for(let s=0;s<3;s++){let r=3*t[a]+s,o=i[r],c=i[3*t[a]+(s+1)%3],l=o<c?o*e+c:c*e+o;n.set(l,n.has(l)?-1:r)}return Int32Array.from([...n.values()].filter(a=>a>=0)).sort()}function AM(i){let t=[1/0,1/0,1/0],e=[-1/0,-1/0,-1/0];for(let s=0;s<i.length;s+=3)for(let r=0;r<3;r++){let o=i[s+r];o<t[r]&&(t[r]=o),o>e[r]&&(e[r]=o)}if(!(t[0]<=e[0]))return{offset:[0,0,0],scale:1};let n=t.map((s,r)=>(s+e[r])/2),a=Math.hypot(e[0]-t[0],e[1]-t[1],e[2]-t[2])/2;return{offset:n,scale:a>0&&Number.isFinite(a)?2/a:1}}var EM=4096;function TM(i){let t=i.length/3,e=[];for(let r of[-1,0,1])for(let o of[-1,0,1])for(let c of[-1,0,1])(r||o||c)&&e.push([r,o,c]);let n=e.map(()=>[-1/0,0]);for(let r=0;r<t;r++){let o=i[3*r],c=i[3*r+1],l=i[3*r+2];for(let h=0;h<e.length;h++){let u=e[h],d=u[0]*o+u[1]*c+u[2]*l;d>n[h][0]&&(n[h]=[d,r])}}let a=new Set(n.map(r=>r[1])),s=Math.max(1,Math.ceil(t/EM));for(let r=0;r<t;r+=s)a.add(r);return[...a].map(r=>new rt(i[3*r],i[3*r+1],i[3*r+2]))}function IM(i,t,e){let n=e.flipped.length?e.flipped:e.boundary.length?e.boundary:e.non_manifold;if(!n.length)return Ln.clone();let a=new rt;for(let s=0;s<n.length;s++){let r=t[n[s]];a.x+=i[3*r],a.y+=i[3*r+1],a.z+=i[3*r+2]}return a.divideScalar(n.length),a.length()>1e-6?a.normalize().multiplyScalar(3).add(Ln).normalize():Ln.clone()}function ra(i,t){if(!t)return new i(0);if(ArrayBuffer.isView(t)&&!(t instanceof DataView))return t;let{buffer:e,byteOffset:n,byteLength:a}=t;return n%i.BYTES_PER_ELEMENT===0?new i(e,n,a/i.BYTES_PER_ELEMENT):new i(e.slice(n,n+a))}function RM(i){let t=i.get("mesh");if(t)return t;let e=i.get("positions");return!e||!e.byteLength?null:{positions:ra(Float64Array,e),faces:ra(Uint32Array,i.get("faces")),flipped:ra(Int32Array,i.get("flipped")),boundary:ra(Int32Array,i.get("boundary")),non_manifold:ra(Int32Array,i.get("non_manifold")),arrow_faces:ra(Int32Array,i.get("arrow_faces")),arrow_normals:ra(Float32Array,i.get("arrow_normals")),vertex_normals:ra(Float32Array,i.get("vertex_normals"))}}function hg(i,t,e){let n=i.length/3,a=new Float32Array(18*n),s=0,r=new rt,o=new rt,c=new rt;for(let l=0;l<n;l++){if(r.set(t[3*l],t[3*l+1],t[3*l+2]),!(r.lengthSq()>0))continue;r.normalize();let h=i[3*l],u=i[3*l+1],d=i[3*l+2],f=h+r.x*e,x=u+r.y*e,v=d+r.z*e;c.set(Math.abs(r.z)<.9?0:1,0,Math.abs(r.z)<.9?1:0),o.crossVectors(r,c).normalize().multiplyScalar(.22*e);let m=f-r.x*.35*e,g=x-r.y*.35*e,y=v-r.z*.35*e;a.set([h,u,d,f,x,v,f,x,v,m+o.x,g+o.y,y+o.z,f,x,v,m-o.x,g-o.y,y-o.z],s),s+=18}return a.subarray(0,s)}function ug(i,t){let e=Math.max(1,Math.ceil(i/t)),n=new Int32Array(Math.ceil(i/e));for(let a=0,s=0;a<i;a+=e,s++)n[s]=a;return n}function CM(i,t){let e=ug(t.length/3,2e3),n=[];for(let a of e){let s=t[3*a],r=t[3*a+1];n.push(Math.hypot(i[3*s]-i[3*r],i[3*s+1]-i[3*r+1],i[3*s+2]-i[3*r+2]))}return n.sort((a,s)=>a-s),n.length?n[n.length>>1]:.1}function NM(){let i=new Fp({side:Zi,flatShading:!0,polygonOffset:!0,polygonOffsetFactor:1,polygonOffsetUnits:1}),t={value:new mi};return i.onBeforeCompile=e=>{let n="vec4 diffuseColor = vec4( diffuse, opacity );";if(!e.fragmentShader.includes(n))throw new Error("mesh view: three.js's Lambert shader changed");e.uniforms.backDiffuse=t,e.fragmentShader=`uniform vec3 backDiffuse;
`+e.fragmentShader.replace(n,"vec4 diffuseColor = vec4( gl_FrontFacing ? diffuse : backDiffuse, opacity );")},i.customProgramCacheKey=()=>"trinormal-two-sided",{material:i,backColor:t.value}}var PM=6e4,ru=3e4;function dg(i,t,e){let n=new Float32Array(3*e);for(let a=0;a<t.length;a++){let s=t[a];s!==4294967295&&(n[3*s]=i[3*a],n[3*s+1]=i[3*a+1],n[3*s+2]=i[3*a+2])}return n}var LM=1500,DM=0;function UM({model:i,el:t}){let e=t.ownerDocument||document,n=i.get("picked")!==void 0;vM(e);let a=Ne("div","tnm-root"),s=Ne("div","tnm-toolbar");s.setAttribute("role","toolbar"),s.setAttribute("aria-label","3D view of the mesh");let r=Ne("div","tnm-stage"),o=Ne("ul","tnm-legend"),c=Ne("p","tnm-hint","Drag to turn the model, scroll or pinch to zoom; on a touch screen, tap the view first, then drag; from the keyboard, Tab to the view and use the arrow keys, + and −. The side a face's normal points out of is drawn in the front colour; a face you see in the back colour from outside is wound the other way."+(n?" Click or tap a face, or type its number in the Face number box, to see its vertices, its exact normal and its area.":"")),l=Ne("form","tnm-keys");l.hidden=!n;let h=`tnm-face-${++DM}`,u=Ne("label","tnm-face-label","Face number");u.htmlFor=h;let d=Ne("input","tnm-face-input");Object.assign(d,{id:h,type:"number",min:"0",step:"1",inputMode:"numeric",autocomplete:"off"});let f=Ne("button","tnm-button","Show face");f.type="submit";let x=Ne("button","tnm-button","Previous face to flip"),v=Ne("button","tnm-button","Next face to flip");x.type=v.type="button",l.append(u,d,f,x,v);let m=Ne("div","tnm-pick");m.setAttribute("aria-live","polite"),m.setAttribute("aria-atomic","true"),m.hidden=!0,a.append(s,r,o,l,m,c),t.appendChild(a);let g=Ss(e),y;try{y=bl(r,{onRender:()=>{}})}catch{return r.remove(),a.appendChild(Ne("p","tnm-nogl","This browser cannot draw the 3D view (WebGL is not available). The report above does not need it.")),()=>a.remove()}let w=y.scene,p=new Np(16777215,1.1),_=new Dp(16777215,1.9);_.position.set(0,0,1),y.camera.add(_),w.add(p,y.camera);let{material:S,backColor:b}=NM(),M={flipped:new qr({linewidth:2.5}),boundary:new qr({linewidth:4}),non_manifold:new qr({linewidth:4})},E=null,A=[],I=null,N=null,L=null,P=!1,U={},V={flipped:new vs,boundary:new vs,non_manifold:new vs},O={},Q={face:new vs,vertex:new vs},G={},Z=null,et=new qr({linewidth:4}),ht={flipped:0,boundary:0,non_manifold:0,face_arrows:0,vertex_arrows:0},Pt={cull:!1,smooth:!1,show_face_normals:!0,show_vertex_normals:!1},Y=R=>{let k=i.get(R);return k==null?Pt[R]:!!k};function ct(R,k){Pt[R]=k,i.get(R)===void 0||i.get(R)===null?Ae():(i.set(R,k),i.save_changes())}let mt=()=>i.get("palette")||{};function Tt(){let R=ta(g);a.classList.toggle("tnm-dark",g),y.setBackground(R.background),S.color=new mi($n(mt(),"front",g)),b.set($n(mt(),"back",g));for(let[k,H]of Object.entries(M))H.color=new mi($n(mt(),k,g));for(let[k,H]of Object.entries(V))H.color=new mi($n(mt(),k,g));Q.face.color=new mi($n(mt(),"N",g)),Q.vertex.color=new mi(R.text),et.color=new mi(R.line),Ot(),y.requestRender()}let gt=[["front","front of a face (its normal points out of this side)","face"],["back","back of a face","face"],["flipped","outline: a face to flip","line"],["boundary","thick: an edge with one face (the rim of a hole)","line"],["non_manifold","thick: an edge with three faces or more","line"],["face_arrows","arrow from a face's centre: its unit normal","arrow"],["vertex_arrows","arrow from a vertex: its vertex normal","arrow"]];function Ot(){o.textContent="";for(let[R,k,H]of gt){if(H==="line"&&!ht[R]||R==="face_arrows"&&!(ht[R]&&Y("show_face_normals"))||R==="vertex_arrows"&&!(ht[R]&&Y("show_vertex_normals")))continue;let j=Ne("li","tnm-key"),it=Ne("span","tnm-swatch tnm-swatch-"+(H==="arrow"?"line":H)),st=R==="face_arrows"?$n(mt(),"N",g):R==="vertex_arrows"?ta(g).text:$n(mt(),R,g);it.style.setProperty("--tnm-swatch",st),it.setAttribute("aria-hidden","true");let _t=R==="flipped"&&ht.flipped>lg,Ct=_t?` (${ht[R]} faces)`:H==="line"?` (${ht[R]})`:H==="arrow"?` (${ht[R]} drawn)`:"";j.append(it,e.createTextNode((_t?"outline: the rim of each patch of faces to flip":k)+Ct)),o.appendChild(j)}}function ge(){for(let R of A)w.remove(R);for(let R of[...Object.values(U),...Object.values(O)])w.remove(R),R.geometry.dispose();O={},P=!1,a.dataset.turning="false";for(let R of Object.values(G))w.remove(R),R.geometry.dispose();E&&E.dispose(),L&&(w.remove(L),L.geometry.dispose(),L=null),N&&N(),I=N=null,A=[],U={},G={},E=null,Dt()}function Dt(){Z&&(w.remove(Z),Z.geometry.dispose(),Z=null)}let kt=null;function Yt(R,k){let H=.5*CM(k,R.faces),j=R.arrow_faces||new Int32Array(0),it=R.arrow_normals||new Float32Array(0);if(j.length&&it.length===3*j.length){let _t=new Float32Array(3*j.length);for(let Ct=0;Ct<j.length;Ct++)for(let ot=0;ot<3;ot++){let vt=R.faces[3*j[Ct]+ot];for(let Ut=0;Ut<3;Ut++)_t[3*Ct+Ut]+=k[3*vt+Ut]/3}G.face=Xt(hg(_t,it,H),Q.face)}let st=R.vertex_normals;if(st&&st.length===k.length){let _t=ug(k.length/3,LM),Ct=new Float32Array(3*_t.length),ot=new Float32Array(3*_t.length);_t.forEach((vt,Ut)=>{for(let pt=0;pt<3;pt++)Ct[3*Ut+pt]=k[3*vt+pt],ot[3*Ut+pt]=st[3*vt+pt]}),G.vertex=Xt(hg(Ct,ot,H),Q.vertex)}ht.face_arrows=G.face?G.face.geometry.getAttribute("position").count/6:0,ht.vertex_arrows=G.vertex?G.vertex.geometry.getAttribute("position").count/6:0}function Xt(R,k){let H=new Ki;H.setAttribute("position",new on(R,3));let j=new Rd(H,k);return j.renderOrder=2,w.add(j),j}function Ae(){let R=Y("cull"),k=Y("smooth"),H=R?Di:Zi;k&&E&&!E.getAttribute("normal")&&E.computeVertexNormals(),(S.side!==H||S.flatShading===k)&&(S.side=H,S.flatShading=!k,S.needsUpdate=!0),G.face&&(G.face.visible=Y("show_face_normals")),G.vertex&&(G.vertex.visible=Y("show_vertex_normals"));for(let[it,st]of Object.entries(at))st.setAttribute("aria-pressed",String(Y(it)));tt.hidden=!G.face,lt.hidden=!G.vertex;let j=kt?kt.data.faces.length/3:0;l.hidden=!n||!j,u.textContent=j?`Face number (0 to ${j-1})`:"Face number",x.hidden=v.hidden=!(kt&&kt.data.flipped&&kt.data.flipped.length),Ot(),y.requestRender()}function nt(){ge();let R=RM(i);if(kt=null,!R||!R.positions||!R.faces){ht.face_arrows=ht.vertex_arrows=0,Ae();return}let{offset:k,scale:H}=AM(R.positions),j=new Float32Array(R.positions.length);for(let vt=0;vt<j.length;vt++)j[vt]=(R.positions[vt]-k[vt%3])*H;E=new Ki,E.setAttribute("position",new on(j,3)),E.setIndex(new on(R.faces,1)),R.vertex_normals&&R.vertex_normals.length===j.length&&E.setAttribute("normal",new on(R.vertex_normals,3)),E.computeBoundingSphere(),A=[new yn(E,S)],w.add(...A);let it=globalThis.requestIdleCallback||(vt=>setTimeout(vt,200)),st=globalThis.cancelIdleCallback||clearTimeout,_t=it(()=>{N=null,B()},{timeout:3e3});N=()=>st(_t);let Ct={flipped:R.flipped?R.flipped.length>lg?wM(R.faces,R.flipped,j.length/3):cg(R.flipped):new Int32Array(0),boundary:R.boundary||new Int32Array(0),non_manifold:R.non_manifold||new Int32Array(0)};a.dataset.flippedSides=String(Ct.flipped.length);let ot=[0,0,0];for(let[vt,Ut]of Object.entries(Ct)){if(ht[vt]=vt==="flipped"?R.flipped?R.flipped.length:0:Ut.length,!Ut.length)continue;let pt=og(j,R.faces,Ut,1,ot),re=new Ki;re.setAttribute("position",new on(pt,3));let Te=new Rd(re,V[vt]);if(Te.renderOrder=1,Te.userData.sides=Ut.length,O[vt]=Te,w.add(Te),Ut.length>MM)continue;let Gn=new Od;Gn.setPositions(pt);let Na=new Ud(Gn,M[vt]);Na.renderOrder=1,U[vt]=Na,w.add(Na)}wt(),y.framePoints(TM(j),!0,IM(j,R.faces,Ct)),R.faces.length/3>PM&&St(E,R.faces,j),Yt(R,j),kt={data:R,pos:j,offset:k,scale:H},T(),Ae(),a.dataset.faces=String(R.faces.length/3),D()}function St(R,k,H){ks.ready.then(()=>{if(E!==R||!ks.supported)return;let j=new Uint32Array(k.buffer,k.byteOffset,k.length),[it]=ks.simplify(j,H,3,3*ru,1);if(it.length>6*ru&&([it]=ks.simplifySloppy(j,H,3,null,3*ru,1)),!it.length)return;let[st,_t]=ks.compactMesh(it),Ct=new Ki;Ct.setAttribute("position",new on(dg(R.getAttribute("position").array,st,_t),3)),Ct.setIndex(new on(it,1)),Ct.boundingSphere=R.boundingSphere,L=new yn(Ct,S),L.userData={remap:st,unique:_t,normal:null},L.visible=!1,w.add(L),a.dataset.coarseFaces=String(it.length/3)})}function wt(){for(let[R,k]of Object.entries(O))U[R]&&(U[R].visible=!P),k.visible=P?k.userData.sides<=SM:!U[R]}function Qt(R){if(!E||P===R||(P=R,wt(),a.dataset.turning=String(R),y.requestRender(),!L))return;let k=E.getAttribute("normal"),H=L.userData;k&&H.normal!==k&&(H.normal=k,L.geometry.setAttribute("normal",new on(dg(k.array,H.remap,H.unique),3))),L.visible=R;for(let j of A)j.visible=!R}let Ht=!1;y.controls.addEventListener("start",()=>{Ht=!0}),y.controls.addEventListener("change",()=>{Ht&&Qt(!0)}),y.controls.addEventListener("end",()=>{Ht=!1,Qt(!1)});let be=new pl,fe=new cn,ne=null;function B(){return!I&&E&&(I=new Wl(E,{indirect:!0,targetLeafSize:32})),I}function Ee(R,k){if(!A.length||!B())return-1;let H=y.canvas.getBoundingClientRect();fe.set((R-H.left)/H.width*2-1,-((k-H.top)/H.height)*2+1),be.setFromCamera(fe,y.camera);let j=I.raycastFirst(be.ray,Y("cull")?Di:Zi);if(!j)return-1;let{offset:it,scale:st}=kt;return a.dataset.pickPoint=j.point.toArray().map((_t,Ct)=>_t/st+it[Ct]).join(","),j.faceIndex}function $t(R){ne=R.button===0?[R.clientX,R.clientY]:null}function Jt(R){i.set("picked",R),i.save_changes(),D()}function dt(R){if(!ne||Math.hypot(R.clientX-ne[0],R.clientY-ne[1])>4||(ne=null,!n))return;let k=Ee(R.clientX,R.clientY);k>=0&&Jt(k)}y.canvas.addEventListener("pointerdown",$t),y.canvas.addEventListener("pointerup",dt),r.tabIndex=0,r.setAttribute("role","img"),r.setAttribute("aria-label","The model in 3D. Arrow keys turn it, + and − zoom, Home resets the view."),r.addEventListener("keydown",R=>{let k=(R.shiftKey?45:15)*(Math.PI/180),j={ArrowLeft:()=>y.turn(-k,0),ArrowRight:()=>y.turn(k,0),ArrowUp:()=>y.turn(0,k),ArrowDown:()=>y.turn(0,-k),"+":()=>y.zoom(.8),"=":()=>y.zoom(.8),"-":()=>y.zoom(1.25),Home:()=>y.reset()}[R.key];!j||R.altKey||R.ctrlKey||R.metaKey||(R.preventDefault(),j())});let se=yl({root:a,stageEl:r,controls:y.controls,canvas:y.canvas,activeClass:"tnm-touch-active"});function At(){let R=d.value.trim();if(!R||!d.checkValidity()){d.reportValidity();return}Jt(Number(R))}l.addEventListener("submit",R=>{R.preventDefault(),At()}),d.addEventListener("keydown",R=>{R.key==="Enter"&&(R.preventDefault(),At())});function Lt(R){let k=kt?kt.data.flipped:null;if(!k||!k.length)return;let H=i.get("picked"),j=R>0?k.findIndex(it=>it>H):k.findLastIndex(it=>it<H);j<0&&(j=R>0?0:k.length-1),d.value=String(k[j]),Jt(k[j])}x.addEventListener("click",()=>Lt(-1)),v.addEventListener("click",()=>Lt(1));function D(){Dt();let R=i.get("picked");if(kt&&Number.isInteger(R)&&R>=0&&R<kt.data.faces.length/3){let H=new Od;H.setPositions(og(kt.pos,kt.data.faces,cg([R]),1,[0,0,0])),Z=new Ud(H,et),Z.renderOrder=3,w.add(Z),a.dataset.picked=String(R),e.activeElement!==d&&(d.value=String(R))}else delete a.dataset.picked;let k=i.get("selection");if(m.textContent="",m.hidden=!(k&&k.rows&&k.rows.length),!m.hidden){m.appendChild(Ne("p","tnm-pick-title",k.title||""));let H=Ne("dl","tnm-pick-rows");for(let[j,it]of k.rows)H.append(Ne("dt","",j),Ne("dd","",it));m.appendChild(H)}y.requestRender()}function T(){let{width:R,height:k}=y.size();for(let H of Object.values(M))H.resolution.set(R,k);et.resolution.set(R,k)}function W(R,k,H){let j=Ne("button","tnm-button",k);return j.type="button",j.setAttribute("aria-pressed","false"),j.title=H,j.addEventListener("click",()=>ct(R,!Y(R))),j}let at={cull:W("cull","Cull back faces","Hide the back of every face, as a game engine does: flipped faces vanish"),smooth:W("smooth","Smooth shading","Light each face with its corners' vertex normals blended, instead of one normal per face"),show_face_normals:W("show_face_normals","Face normals","Show each face's unit normal as an arrow from its centre"),show_vertex_normals:W("show_vertex_normals","Vertex normals","Show the vertex normals as arrows from the vertices")},tt=at.show_face_normals,lt=at.show_vertex_normals;tt.hidden=lt.hidden=!0;let ut=Ne("button","tnm-button","Reset view");ut.type="button",ut.addEventListener("click",()=>y.reset()),s.append(ut,...Object.values(at));let $=new ResizeObserver(()=>{T(),y.requestRender()});$.observe(r);let J=xl(R=>{g=R,Tt()},e),ft=[["change:mesh",nt],["change:revision",nt],["change:palette",Tt],["change:picked",D],["change:selection",D],...Object.keys(Pt).map(R=>["change:"+R,Ae])];for(let[R,k]of ft)i.on(R,k);return Tt(),nt(),()=>{for(let[R,k]of ft)i.off(R,k);y.canvas.removeEventListener("pointerdown",$t),y.canvas.removeEventListener("pointerup",dt),se.dispose(),$.disconnect(),J(),ge(),S.dispose();for(let R of[...Object.values(M),...Object.values(V)])R.dispose();for(let R of Object.values(Q))R.dispose();et.dispose(),y.dispose(),a.remove()}}var ou={render:UM};function OM(i){return(i.model.get("_view")==="mesh"?ou:Dd).render(i)}var FM={render:OM};return Pa(BM);})();
return tnxModule})());
export default R.default;
export const explorer=R.explorer,mesh=R.mesh;
