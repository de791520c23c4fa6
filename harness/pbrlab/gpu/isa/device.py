"""One Vulkan device that compiles pipelines and reports what its compiler made of them.

Used with Mesa's RADV on a "null" device (``RADV_FORCE_FAMILY``, no GPU present): RADV
compiles with ACO for the forced GPU family and answers
``vkGetPipelineExecutableStatisticsKHR`` (instructions, registers, ACO's latency and
throughput estimates) and ``...InternalRepresentationsKHR`` (the disassembly). Nothing is
ever submitted: there is nothing to run it on."""

from __future__ import annotations

import ctypes
import os
from ctypes import POINTER, byref, c_char_p, c_float, c_uint32, c_void_p
from dataclasses import dataclass, field

from ...foundation.errors import PbrlabError
from . import vulkan as vk

_EXTENSION = b"VK_KHR_pipeline_executable_properties"
_FLOAT16 = b"VK_KHR_shader_float16_int8"


@dataclass
class Executable:
    """One compiled shader stage: its statistics by name and its disassembly."""
    name: str
    stages: int
    subgroup_size: int = 0    # the wave size it was compiled for (32 or 64)
    statistics: dict = field(default_factory=dict)
    disassembly: str = ""


class Device:
    """The first physical device whose name contains ``name_contains``."""

    def __init__(self, name_contains: str = "RADV"):
        self.lib = lib = vk.load_loader()
        lib.vkGetInstanceProcAddr.restype = c_void_p
        lib.vkGetInstanceProcAddr.argtypes = [c_void_p, c_char_p]
        self._instance = c_void_p()
        app = vk.ApplicationInfo(vk.ST_APPLICATION_INFO, None, b"pbrlab", 1, b"pbrlab", 1,
                                 vk.API_VERSION_1_2)
        info = vk.InstanceCreateInfo(vk.ST_INSTANCE_CREATE_INFO, None, 0, ctypes.pointer(app),
                                     0, None, 0, None)
        create = self._global("vkCreateInstance", [c_void_p, c_void_p, POINTER(c_void_p)])
        vk.check(create(byref(info), None, byref(self._instance)), "vkCreateInstance")
        self.physical, self.name = self._pick(name_contains)
        self.float16 = self._create_device()

    # ---- function pointers ----------------------------------------------------------------
    def _global(self, name, argtypes):
        address = self.lib.vkGetInstanceProcAddr(None, name.encode())
        return ctypes.CFUNCTYPE(ctypes.c_int32, *argtypes)(address)

    def _fn(self, name, argtypes, restype=ctypes.c_int32):
        address = self.lib.vkGetInstanceProcAddr(self._instance, name.encode())
        if not address:
            raise vk.VulkanUnavailable(f"the Vulkan loader has no {name}")
        return ctypes.CFUNCTYPE(restype, *argtypes)(address)

    def _dfn(self, name, argtypes, restype=ctypes.c_int32):
        get = self._fn("vkGetDeviceProcAddr", [c_void_p, c_char_p], c_void_p)
        address = get(self.device, name.encode())
        if not address:
            raise vk.VulkanUnavailable(f"the device has no {name}")
        return ctypes.CFUNCTYPE(restype, *argtypes)(address)

    # ---- set-up ---------------------------------------------------------------------------
    def _pick(self, name_contains):
        enumerate_ = self._fn("vkEnumeratePhysicalDevices",
                              [c_void_p, POINTER(c_uint32), POINTER(c_void_p)])
        count = c_uint32()
        vk.check(enumerate_(self._instance, byref(count), None), "vkEnumeratePhysicalDevices")
        devices = (c_void_p * count.value)()
        vk.check(enumerate_(self._instance, byref(count), devices), "vkEnumeratePhysicalDevices")
        properties = self._fn("vkGetPhysicalDeviceProperties", [c_void_p, c_void_p], None)
        names = []
        for physical in devices:
            buffer = ctypes.create_string_buffer(4096)  # VkPhysicalDeviceProperties is 824 bytes
            properties(physical, buffer)
            name = vk.text(buffer.raw[20:20 + 256])  # after apiVersion ... deviceType (5 uint32)
            names.append(name)
            if name_contains in name:
                return c_void_p(physical), name
        raise vk.VulkanUnavailable(
            f"no Vulkan device named '*{name_contains}*' (found: {', '.join(names) or 'none'}); "
            "RADV's null device needs mesa-vulkan-drivers and RADV_FORCE_FAMILY")

    def _extensions(self) -> set:
        list_ = self._fn("vkEnumerateDeviceExtensionProperties",
                         [c_void_p, c_char_p, POINTER(c_uint32), c_void_p])
        count = c_uint32()
        vk.check(list_(self.physical, None, byref(count), None), "device extensions")
        props = (vk.ExtensionProperties * count.value)()
        vk.check(list_(self.physical, None, byref(count), props), "device extensions")
        return {p.extensionName for p in props}

    def _create_device(self) -> bool:
        extensions = self._extensions()
        if _EXTENSION not in extensions:
            raise vk.VulkanUnavailable(f"{self.name} lacks {_EXTENSION.decode()}")
        # what the device offers of shaderFloat16 (VkPhysicalDeviceShaderFloat16Int8Features)
        f16 = vk.Float16Int8Features(vk.ST_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES, None, 0, 0)
        query = vk.PhysicalDeviceFeatures2(vk.ST_PHYSICAL_DEVICE_FEATURES_2,
                                           ctypes.cast(byref(f16), c_void_p))
        self._fn("vkGetPhysicalDeviceFeatures2", [c_void_p, c_void_p], None)(self.physical,
                                                                              byref(query))
        float16 = bool(f16.shaderFloat16) and _FLOAT16 in extensions
        pipeline_exec = vk.PipelineExecutableFeatures(
            vk.ST_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR, None, 1)
        wanted = vk.Float16Int8Features(vk.ST_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES,
                                        ctypes.cast(byref(pipeline_exec), c_void_p),
                                        int(float16), 0)
        names = [_EXTENSION] + ([_FLOAT16] if float16 else [])
        ext_array = (c_char_p * len(names))(*names)
        priority = c_float(1.0)
        queue = vk.DeviceQueueCreateInfo(vk.ST_DEVICE_QUEUE_CREATE_INFO, None, 0, 0, 1,
                                         ctypes.pointer(priority))
        self._keep = (pipeline_exec, wanted, ext_array, priority, queue)
        info = vk.DeviceCreateInfo(vk.ST_DEVICE_CREATE_INFO, ctypes.cast(byref(wanted), c_void_p),
                                   0, 1, ctypes.pointer(queue), 0, None, len(names), ext_array, None)
        self.device = c_void_p()
        create = self._fn("vkCreateDevice", [c_void_p, c_void_p, c_void_p, POINTER(c_void_p)])
        vk.check(create(self.physical, byref(info), None, byref(self.device)), "vkCreateDevice")
        self._bind_device_functions()
        return float16

    def _bind_device_functions(self):
        H = vk.Handle
        self._create_module = self._dfn("vkCreateShaderModule",
                                        [c_void_p, c_void_p, c_void_p, POINTER(H)])
        self._destroy_module = self._dfn("vkDestroyShaderModule", [c_void_p, H, c_void_p], None)
        self._create_set_layout = self._dfn("vkCreateDescriptorSetLayout",
                                            [c_void_p, c_void_p, c_void_p, POINTER(H)])
        self._destroy_set_layout = self._dfn("vkDestroyDescriptorSetLayout",
                                             [c_void_p, H, c_void_p], None)
        self._create_layout = self._dfn("vkCreatePipelineLayout",
                                        [c_void_p, c_void_p, c_void_p, POINTER(H)])
        self._destroy_layout = self._dfn("vkDestroyPipelineLayout", [c_void_p, H, c_void_p], None)
        self._create_render_pass = self._dfn("vkCreateRenderPass",
                                             [c_void_p, c_void_p, c_void_p, POINTER(H)])
        self._destroy_render_pass = self._dfn("vkDestroyRenderPass",
                                              [c_void_p, H, c_void_p], None)
        self._create_graphics = self._dfn("vkCreateGraphicsPipelines",
                                          [c_void_p, H, c_uint32, c_void_p, c_void_p, POINTER(H)])
        self._destroy_pipeline = self._dfn("vkDestroyPipeline", [c_void_p, H, c_void_p], None)
        self._executables = self._dfn("vkGetPipelineExecutablePropertiesKHR",
                                      [c_void_p, c_void_p, POINTER(c_uint32), c_void_p])
        self._statistics = self._dfn("vkGetPipelineExecutableStatisticsKHR",
                                     [c_void_p, c_void_p, POINTER(c_uint32), c_void_p])
        self._representations = self._dfn("vkGetPipelineExecutableInternalRepresentationsKHR",
                                          [c_void_p, c_void_p, POINTER(c_uint32), c_void_p])

    # ---- objects --------------------------------------------------------------------------
    def _module(self, spirv: bytes):
        words = ctypes.create_string_buffer(spirv, len(spirv))
        info = vk.ShaderModuleCreateInfo(vk.ST_SHADER_MODULE_CREATE_INFO, None, 0, len(spirv),
                                         ctypes.cast(words, c_void_p))
        module = vk.Handle()
        vk.check(self._create_module(self.device, byref(info), None, byref(module)),
                 "vkCreateShaderModule")
        return module

    def _layout(self, sets: dict):
        """A pipeline layout from ``{set: [(binding, descriptor type, count), ...]}``."""
        set_layouts = []
        for index in range(max(sets) + 1 if sets else 0):
            rows = sets.get(index, [])
            bindings = (vk.DescriptorSetLayoutBinding * max(1, len(rows)))()
            for i, (binding, kind, count) in enumerate(rows):
                bindings[i] = vk.DescriptorSetLayoutBinding(binding, kind, count, vk.STAGE_ALL, None)
            info = vk.DescriptorSetLayoutCreateInfo(vk.ST_DESCRIPTOR_SET_LAYOUT_CREATE_INFO, None,
                                                    0, len(rows), bindings)
            handle = vk.Handle()
            vk.check(self._create_set_layout(self.device, byref(info), None, byref(handle)),
                     "vkCreateDescriptorSetLayout")
            set_layouts.append(handle.value)
        handles = (vk.Handle * max(1, len(set_layouts)))(*set_layouts)
        info = vk.PipelineLayoutCreateInfo(vk.ST_PIPELINE_LAYOUT_CREATE_INFO, None, 0,
                                           len(set_layouts), handles, 0, None)
        layout = vk.Handle()
        vk.check(self._create_layout(self.device, byref(info), None, byref(layout)),
                 "vkCreatePipelineLayout")
        return layout, set_layouts

    def _render_pass(self, colour_count: int):
        attachments = (vk.AttachmentDescription * max(1, colour_count))()
        refs = (vk.AttachmentReference * max(1, colour_count))()
        for i in range(colour_count):
            # 1 sample, load DONT_CARE(2), store STORE(0), layouts UNDEFINED -> GENERAL(1)
            attachments[i] = vk.AttachmentDescription(0, vk.FORMAT_R32G32B32A32_SFLOAT, 1, 2, 0,
                                                      2, 1, 0, 1)
            refs[i] = vk.AttachmentReference(i, 1)
        subpass = vk.SubpassDescription(0, 0, 0, None, colour_count, refs, None, None, 0, None)
        info = vk.RenderPassCreateInfo(vk.ST_RENDER_PASS_CREATE_INFO, None, 0, colour_count,
                                       attachments, 1, ctypes.pointer(subpass), 0, None)
        handle = vk.Handle()
        vk.check(self._create_render_pass(self.device, byref(info), None, byref(handle)),
                 "vkCreateRenderPass")
        return handle

    def _stage(self, stage, module, entry=b"main"):
        return vk.PipelineShaderStageCreateInfo(vk.ST_PIPELINE_SHADER_STAGE_CREATE_INFO, None, 0,
                                                stage, module, entry, None)

    _FLAGS = vk.PIPELINE_CREATE_CAPTURE_STATISTICS | vk.PIPELINE_CREATE_CAPTURE_INTERNAL_REPRESENTATIONS

    def graphics(self, vertex: bytes, fragment: bytes, sets: dict, colour_count: int) -> list:
        """The executables of a graphics pipeline: one triangle list, no vertex buffers, no
        depth, ``colour_count`` RGBA32F attachments without blending."""
        vmodule, fmodule = self._module(vertex), self._module(fragment)
        layout, set_layouts = self._layout(sets)
        render_pass = self._render_pass(colour_count)
        stages = (vk.PipelineShaderStageCreateInfo * 2)(self._stage(vk.STAGE_VERTEX, vmodule),
                                                        self._stage(vk.STAGE_FRAGMENT, fmodule))
        vertex_input = vk.VertexInputStateCreateInfo(vk.ST_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
                                                     None, 0, 0, None, 0, None)
        assembly = vk.InputAssemblyStateCreateInfo(vk.ST_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
                                                   None, 0, 3, 0)  # TRIANGLE_LIST
        viewport = vk.ViewportStateCreateInfo(vk.ST_PIPELINE_VIEWPORT_STATE_CREATE_INFO, None, 0,
                                              1, None, 1, None)
        raster = vk.RasterizationStateCreateInfo(vk.ST_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
                                                 None, 0, 0, 0, 0, 0, 0, 0, 0.0, 0.0, 0.0, 1.0)
        multisample = vk.MultisampleStateCreateInfo(vk.ST_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
                                                    None, 0, 1, 0, 0.0, None, 0, 0)
        blends = (vk.ColorBlendAttachmentState * max(1, colour_count))()
        for i in range(colour_count):
            blends[i] = vk.ColorBlendAttachmentState(0, 1, 0, 0, 1, 0, 0, 0xF)
        blend = vk.ColorBlendStateCreateInfo(vk.ST_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO, None, 0,
                                             0, 0, colour_count, blends, (c_float * 4)())
        dynamic_states = (c_uint32 * 2)(vk.DYNAMIC_STATE_VIEWPORT, vk.DYNAMIC_STATE_SCISSOR)
        dynamic = vk.DynamicStateCreateInfo(vk.ST_PIPELINE_DYNAMIC_STATE_CREATE_INFO, None, 0, 2,
                                            dynamic_states)
        info = vk.GraphicsPipelineCreateInfo(
            vk.ST_GRAPHICS_PIPELINE_CREATE_INFO, None, self._FLAGS, 2, stages,
            ctypes.pointer(vertex_input), ctypes.pointer(assembly), None, ctypes.pointer(viewport),
            ctypes.pointer(raster), ctypes.pointer(multisample), None, ctypes.pointer(blend),
            ctypes.pointer(dynamic), layout, render_pass, 0, 0, -1)
        try:
            return self._pipeline(self._create_graphics, info)
        finally:
            self._destroy_render_pass(self.device, render_pass, None)
            self._release(vmodule, layout, set_layouts)
            self._destroy_module(self.device, fmodule, None)

    def _release(self, module, layout, set_layouts):
        self._destroy_module(self.device, module, None)
        self._destroy_layout(self.device, layout, None)
        for handle in set_layouts:
            self._destroy_set_layout(self.device, handle, None)

    def _pipeline(self, create, info) -> list:
        pipeline = vk.Handle()
        result = create(self.device, 0, 1, byref(info), None, byref(pipeline))
        if result != vk.SUCCESS:
            raise PbrlabError(f"{self.name}: the pipeline did not compile (VkResult {result})")
        try:
            return self._read_executables(pipeline)
        finally:
            self._destroy_pipeline(self.device, pipeline, None)

    def _read_executables(self, pipeline) -> list:
        pinfo = vk.PipelineInfo(vk.ST_PIPELINE_INFO_KHR, None, pipeline)
        count = c_uint32()
        vk.check(self._executables(self.device, byref(pinfo), byref(count), None), "executables")
        props = (vk.PipelineExecutableProperties * count.value)()
        for p in props:
            p.sType = vk.ST_PIPELINE_EXECUTABLE_PROPERTIES_KHR
        vk.check(self._executables(self.device, byref(pinfo), byref(count), props), "executables")
        out = []
        for index, p in enumerate(props):
            executable = Executable(vk.text(p.name), p.stages, p.subgroupSize)
            einfo = vk.PipelineExecutableInfo(vk.ST_PIPELINE_EXECUTABLE_INFO_KHR, None, pipeline,
                                              index)
            executable.statistics = self._read_statistics(einfo)
            executable.disassembly = self._read_disassembly(einfo)
            out.append(executable)
        return out

    def _read_statistics(self, einfo) -> dict:
        count = c_uint32()
        vk.check(self._statistics(self.device, byref(einfo), byref(count), None), "statistics")
        stats = (vk.PipelineExecutableStatistic * count.value)()
        for s in stats:
            s.sType = vk.ST_PIPELINE_EXECUTABLE_STATISTIC_KHR
        vk.check(self._statistics(self.device, byref(einfo), byref(count), stats), "statistics")
        values = {}
        for s in stats:
            value = {vk.STAT_BOOL32: lambda v: bool(v.b32), vk.STAT_INT64: lambda v: v.i64,
                     vk.STAT_UINT64: lambda v: v.u64, vk.STAT_FLOAT64: lambda v: v.f64}[s.format]
            values[vk.text(s.name)] = value(s.value)
        return values

    def _read_disassembly(self, einfo) -> str:
        count = c_uint32()
        vk.check(self._representations(self.device, byref(einfo), byref(count), None),
                 "internal representations")
        reps = (vk.PipelineExecutableInternalRepresentation * count.value)()
        for r in reps:
            r.sType = vk.ST_PIPELINE_EXECUTABLE_INTERNAL_REPRESENTATION_KHR
        vk.check(self._representations(self.device, byref(einfo), byref(count), reps),
                 "internal representations")
        buffers = []
        for r in reps:
            buffer = ctypes.create_string_buffer(r.dataSize)
            r.pData = ctypes.cast(buffer, c_void_p)
            buffers.append(buffer)
        result = self._representations(self.device, byref(einfo), byref(count), reps)
        if result not in (vk.SUCCESS, 5):  # VK_INCOMPLETE
            vk.check(result, "internal representations")
        for r, buffer in zip(reps, buffers):
            if "disassembly" in vk.text(r.name).lower() or "assembly" in vk.text(r.description).lower():
                return buffer.raw.split(b"\0", 1)[0].decode("utf-8", "replace")
        return ""
